// SPDX-License-Identifier: Apache-2.0
// Test support for the planning tests: running maxima of the finite differences of a signal
// sampled every h seconds (the way the controller sees a plan), and random poses.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Geometry>

namespace planning_test {

constexpr double kCycle = 1e-3;  // s: the RCI cycle every plan is sampled at

// Feeds samples x(t0), x(t0 + h), ... of an N-vector signal. For k = 1, 2, 3 it keeps the largest
// |k-th backward difference| / h^k, per component and as a Euclidean norm. Those quotients are
// weighted averages of the k-th derivative, so they never exceed its largest value.
template <int N>
struct DifferenceMaxima {
  using Vector = Eigen::Matrix<double, N, 1>;

  explicit DifferenceMaxima(double h = kCycle) : h(h) {}

  void add(const Vector& x) {
    window[3] = window[2];
    window[2] = window[1];
    window[1] = window[0];
    window[0] = x;
    largest_value = std::max(largest_value, x.cwiseAbs().maxCoeff());
    ++count;
    if (count >= 2) record(0, (window[0] - window[1]) / h);
    if (count >= 3) record(1, (window[0] - 2 * window[1] + window[2]) / (h * h));
    if (count >= 4) record(2, (window[0] - 3 * window[1] + 3 * window[2] - window[3]) / (h * h * h));
  }

  // Largest rounding error a k-th difference quotient can carry for signals of this size.
  double roundingBound(int order) const {
    const double terms = order == 1 ? 2 : (order == 2 ? 4 : 8);
    return 4 * terms * std::numeric_limits<double>::epsilon() * (1 + largest_value) / std::pow(h, order);
  }

  // order 1..3
  double maxNorm(int order) const { return norm[order - 1]; }
  double maxComponent(int order, int i) const { return component[order - 1](i); }

  double h;
  std::array<Vector, 4> window{};
  int count = 0;
  double largest_value = 0;
  std::array<double, 3> norm{0, 0, 0};
  std::array<Vector, 3> component{Vector::Zero(), Vector::Zero(), Vector::Zero()};

 private:
  void record(int k, const Vector& quotient) {
    norm[k] = std::max(norm[k], quotient.norm());
    component[k] = component[k].cwiseMax(quotient.cwiseAbs());
  }
};

// True when a measured rate stays within limit (relative 1e-9) plus the rounding bound.
inline bool withinLimit(double measured, double limit, double rounding) {
  return measured <= limit * (1 + 1e-9) + rounding;
}

// A uniformly distributed rotation.
inline Eigen::Matrix3d randomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

inline Eigen::Vector3d randomVector(std::mt19937_64& rng, double half_width) {
  std::uniform_real_distribution<double> uniform(-half_width, half_width);
  return {uniform(rng), uniform(rng), uniform(rng)};
}

inline Eigen::Isometry3d makePose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& position) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = position;
  return pose;
}

// Rotation angle between two orientations, in [0, pi].
inline double angleBetween(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(Eigen::Quaterniond(a.transpose() * b).normalized()).angle();
}

}  // namespace planning_test
