// SPDX-License-Identifier: Apache-2.0
// Velocity, acceleration and jerk of a signal known only at the instants commands arrived, by
// divided differences over the (possibly irregular) sample times. A lost packet widens one
// interval instead of doubling a step, so it does not by itself look like a velocity or
// acceleration jump. Exact for polynomials up to degree 3. Allocation-free.
#pragma once

#include <array>

#include <Eigen/Core>

namespace xmate::sim {

template <int N>
class SampledDerivatives {
 public:
  using Vec = Eigen::Matrix<double, N, 1>;

  // A history of rest: the signal stood still at the samples t_last, t_last - dt, t_last - 2 dt.
  void reset(double t_last, double dt) {
    times_ = {t_last, t_last - dt, t_last - 2 * dt};
    velocity_ = acceleration_ = jerk_ = Vec::Zero();
  }

  // The next sample at time t (> the previous one), given as its increment over the previous sample.
  void push(const Vec& increment, double t) {
    const Vec v = increment / (t - times_[0]);
    const Vec a = 2.0 * (v - velocity_) / (t - times_[1]);
    jerk_ = 3.0 * (a - acceleration_) / (t - times_[2]);
    velocity_ = v;
    acceleration_ = a;
    times_ = {t, times_[0], times_[1]};
  }

  const Vec& velocity() const { return velocity_; }
  const Vec& acceleration() const { return acceleration_; }
  const Vec& jerk() const { return jerk_; }
  double lastTime() const { return times_[0]; }

 private:
  std::array<double, 3> times_{0, 0, 0};  // newest first
  Vec velocity_ = Vec::Zero();
  Vec acceleration_ = Vec::Zero();
  Vec jerk_ = Vec::Zero();
};

}  // namespace xmate::sim
