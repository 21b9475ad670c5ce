// SPDX-License-Identifier: Apache-2.0
// Helpers of the model tests (see model_test_support.h).
#include "model_test_support.h"

#include <cmath>

namespace xmate::model::test {

Chain dhChainWithInertias(const RobotSpec& spec, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), moment(0.005, 0.05);
  Chain chain = chainFromDh(spec);
  for (int i = 0; i < spec.dof; ++i) {
    ChainLink& link = chain.links[i];
    link.mass = spec.link_mass[i + 1];
    link.com = 0.1 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    // Principal moments a, b, c with each at most the sum of the other two.
    double a = moment(rng), b = moment(rng), c = moment(rng);
    c = std::min(c, a + b);
    const Eigen::Matrix3d axes =
        Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized().toRotationMatrix();
    link.inertia = axes * Eigen::Vector3d(a, b, c).asDiagonal() * axes.transpose();
    link.inertia = 0.5 * (link.inertia + link.inertia.transpose()).eval();
  }
  return chain;
}

JointVector randomConfiguration(const RobotSpec& spec, std::mt19937& rng, double margin) {
  JointVector q = JointVector::Zero();
  for (int i = 0; i < spec.dof; ++i) {
    std::uniform_real_distribution<double> d(spec.q_min[i] + margin, spec.q_max[i] - margin);
    q[i] = d(rng);
  }
  return q;
}

std::array<double, 7> toArray(const JointVector& q) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[i] = q[i];
  return a;
}

JointVector fromArray(const std::array<double, 7>& q) {
  JointVector v;
  for (int i = 0; i < 7; ++i) v[i] = q[i];
  return v;
}

std::array<Eigen::Isometry3d, 8> dhFrames(const RobotSpec& spec, const JointVector& q) {
  std::array<Eigen::Isometry3d, 8> frames;
  frames.fill(Eigen::Isometry3d::Identity());
  for (int i = 0; i < spec.dof; ++i) {
    const DhRow& r = spec.dh[i];
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.rotate(Eigen::AngleAxisd(r.theta + r.axis_sign * q[i], Eigen::Vector3d::UnitZ()));
    step.translate(Eigen::Vector3d(r.a, 0, r.d));
    step.rotate(Eigen::AngleAxisd(r.alpha, Eigen::Vector3d::UnitX()));
    frames[i + 1] = frames[i] * step;
  }
  return frames;
}

double positionError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

double rotationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Quaterniond d(a.linear().transpose() * b.linear());
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

Eigen::Isometry3d fromRowMajor(const std::array<double, 16>& m) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.matrix() = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m.data());
  return t;
}

std::array<double, 16> toRowMajor(const Eigen::Isometry3d& pose) {
  std::array<double, 16> a{};
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data()) = pose.matrix();
  return a;
}

}  // namespace xmate::model::test
