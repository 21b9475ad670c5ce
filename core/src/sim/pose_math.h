// SPDX-License-Identifier: Apache-2.0
// Small conversions and rotation helpers the simulated controller uses between the wire's
// std::arrays (row-major 4x4 poses, 7-element joint arrays) and Eigen. Allocation-free.
#pragma once

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "model/arm_model.h"

namespace xmate::sim {

using model::JointVector;
using model::Vector6d;

inline JointVector toJointVector(const std::array<double, 7>& a, int dof) {
  JointVector v = JointVector::Zero();
  for (int i = 0; i < dof; ++i) v[i] = a[static_cast<size_t>(i)];
  return v;
}

inline std::array<double, 7> toArray7(const JointVector& v) {
  std::array<double, 7> a{};
  for (int i = 0; i < 7; ++i) a[static_cast<size_t>(i)] = v[i];
  return a;
}

inline std::array<double, 6> toArray6(const Vector6d& v) {
  std::array<double, 6> a{};
  for (int i = 0; i < 6; ++i) a[static_cast<size_t>(i)] = v[i];
  return a;
}

inline Vector6d toVector6(const std::array<double, 6>& a) {
  return Eigen::Map<const Vector6d>(a.data());
}

inline Eigen::Matrix4d toMatrix4(const std::array<double, 16>& row_major) {
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(row_major.data());
}

// The pose of a row-major 4x4 whose rotation is assumed orthonormal (check it first).
inline Eigen::Isometry3d toIsometry(const std::array<double, 16>& row_major) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const Eigen::Matrix4d m = toMatrix4(row_major);
  pose.linear() = m.topLeftCorner<3, 3>();
  pose.translation() = m.topRightCorner<3, 1>();
  return pose;
}

inline std::array<double, 16> toRowMajor(const Eigen::Isometry3d& pose) {
  std::array<double, 16> a{};
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(a.data()) = pose.matrix();
  return a;
}

// Rotation vector (axis * angle, angle in [0, pi]) of a rotation matrix.
inline Eigen::Vector3d rotationLog(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.angle() * aa.axis();
}

// Rotation matrix of a rotation vector.
inline Eigen::Matrix3d rotationExp(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

// [p_target - p_actual; rotation vector of R_target R_actual^T], both in the base frame: the
// small twist that takes `actual` to `target`.
inline Vector6d poseError(const Eigen::Isometry3d& target, const Eigen::Isometry3d& actual) {
  Vector6d e;
  e.head<3>() = target.translation() - actual.translation();
  e.tail<3>() = rotationLog(target.linear() * actual.linear().transpose());
  return e;
}

// Angle wrapped into (-pi, pi].
inline double wrapAngle(double a) {
  constexpr double kPi = 3.14159265358979323846;
  a = std::remainder(a, 2.0 * kPi);
  return a <= -kPi ? a + 2.0 * kPi : a;
}

}  // namespace xmate::sim
