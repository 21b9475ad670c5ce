// SPDX-License-Identifier: Apache-2.0
// The executor's time scaling: plan time advances k * dt per cycle, k in [0, 1]. k follows its
// target (0 to pause or stop, the speed override otherwise) with a bounded rate |dk/dt| <= rate and
// a bounded change of that rate |d2k/dt2| <= rate_change, both set every cycle from the plan's
// current velocity and acceleration, so the commanded motion stays on its path and its velocity,
// acceleration and jerk stay within the limits (docs/teach.md, "Pause and override" and "Stopping
// distance"). Allocation-free; used on the real-time thread.
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
  // The smallest bound on the rate's change, and the one used until setLimits: the jerk a ramp adds
  // (v_plan d2k/dt2 <= 0.8 * 2.61 rad/s * 20 = 42 rad/s^3) is then well within the 20 % of the
  // jerk limits the plans leave free at any plan velocity.
  static constexpr double kRateChange = 20.0;  // 1/s^2

  explicit TimeScaling(double k = 1.0, double rate = kMinRate) : value_(k), target_(k), max_rate_(rate) {}
  void setTarget(double k);  // clamped to [0, 1]
  // Limits for the next steps, e.g. from the plan's current velocity and acceleration
  // (planScalingLimits); each clamped to at least the lower bound of its range.
  void setLimits(double max_rate, double max_rate_change);
  double target() const { return target_; }
  double value() const { return value_; }
  double rate() const { return rate_; }
  double maxRate() const { return max_rate_; }
  double maxRateChange() const { return max_rate_change_; }
  bool settled() const { return value_ == target_ && rate_ == 0; }
  // Advances one cycle of dt seconds.
  void step(double dt);

 private:
  double value_, target_;
  double max_rate_;
  double max_rate_change_ = kRateChange;
  double rate_ = 0;
};

// Limits for k at the plan's current speed. With plan velocity v and acceleration a, the command's
// velocity is k v, its acceleration a k^2 + v dk/dt and its jerk gains v d2k/dt2; so a group of
// coordinates (a joint, or the TCP translation) stays within acceleration A and adds at most jerk J
// when dk/dt <= (A - |a| k^2) / |v| and d2k/dt2 <= J / |v|. Given per group the norms of v and a and
// its A and J, returns the smallest of each over the groups, with a 10 % margin, clamped to
// [kMinRate, kMaxRate] and [kRateChange, kMaxRateChange]. A stop then brakes the way the plan
// could at this point (about v^2 / 2A of travel) instead of at the rate the worst point of the
// whole move allows (docs/teach.md, "Stopping distance").
struct ScalingLimits {
  double rate = TimeScaling::kMinRate;
  double rate_change = TimeScaling::kRateChange;
};
inline constexpr double kMaxRateChange = 1000.0;  // 1/s^2: k from 0 to full rate change in 10 ms
struct GroupMotion {
  double velocity = 0, acceleration = 0;  // norms of the plan's
  double acceleration_limit = 0, jerk_reserve = 0;
};
ScalingLimits planScalingLimits(const GroupMotion* groups, int count, double k);

}  // namespace xmate::teach
