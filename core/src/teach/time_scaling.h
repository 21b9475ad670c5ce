// SPDX-License-Identifier: Apache-2.0
// The executor's time scaling: plan time advances k * dt per cycle, k in [0, 1]. k follows its
// target (0 to pause or stop, the speed override otherwise) with a bounded rate |dk/dt| <= rate and
// a bounded change of that rate |d2k/dt2| <= rate_change, so the commanded motion stays on its path
// and its velocity, acceleration and jerk stay within the limits (docs/teach.md, "Pause and
// override"). Allocation-free; used on the real-time thread.
#pragma once

namespace xmate::teach {

// The fastest ramp of k that keeps a plan within its limits. A plan using `share` (0 < share < 1)
// of the velocity and acceleration limits V and A has |a| = |a_plan k^2 + v_plan dk/dt| <=
// share A + share V rate; that stays within A for rate <= (1 - share) / share * A / V.
// accel_over_velocity is the smallest A / V of the quantities that are limited (joints, or TCP
// translation, rotation and arm angle). Returns a rate in [kMinRate, kMaxRate] (1/s), with a 10 %
// margin.
double safeScalingRate(double share, double accel_over_velocity);

class TimeScaling {
 public:
  static constexpr double kMinRate = 0.5;   // 1/s
  static constexpr double kMaxRate = 10.0;  // 1/s
  // Bounds the jerk a ramp adds (v_plan d2k/dt2 <= 0.8 * 2.61 rad/s * 20 = 42 rad/s^3, well
  // within the 20 % of the jerk limits the plans leave free).
  static constexpr double kRateChange = 20.0;  // 1/s^2

  explicit TimeScaling(double k = 1.0, double rate = kMinRate) : value_(k), target_(k), max_rate_(rate) {}
  void setTarget(double k);  // clamped to [0, 1]
  double target() const { return target_; }
  double value() const { return value_; }
  double rate() const { return rate_; }
  double maxRate() const { return max_rate_; }
  bool settled() const { return value_ == target_ && rate_ == 0; }
  // Advances one cycle of dt seconds.
  void step(double dt);

 private:
  double value_, target_;
  double max_rate_;
  double rate_ = 0;
};

}  // namespace xmate::teach
