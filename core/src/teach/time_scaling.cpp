// SPDX-License-Identifier: Apache-2.0
// TimeScaling (time_scaling.h): a rate- and rate-change-limited tracker. It brakes along the
// discrete form of v = sqrt(2 A |e|): with the rate falling by d = A dt per step, a rate n d covers
// dt d n (n + 1) / 2 before it reaches zero, so the largest rate that can still stop in |e| is
// d (sqrt(1/4 + 2 |e| / (dt d)) - 1/2). It arrives at its target without overshoot.
#include "teach/time_scaling.h"

#include <algorithm>
#include <cmath>

namespace xmate::teach {

double safeScalingRate(double share, double accel_over_velocity) {
  if (!(share > 0 && share < 1) || !(accel_over_velocity > 0)) return TimeScaling::kMinRate;
  const double rate = 0.9 * (1 - share) / share * accel_over_velocity;
  return std::clamp(rate, TimeScaling::kMinRate, TimeScaling::kMaxRate);
}

void TimeScaling::setTarget(double k) { target_ = std::clamp(std::isfinite(k) ? k : 0.0, 0.0, 1.0); }

void TimeScaling::setLimits(double max_rate, double max_rate_change) {
  max_rate_ = std::isfinite(max_rate) ? std::max(max_rate, kMinRate) : kMinRate;
  max_rate_change_ = std::isfinite(max_rate_change) ? std::max(max_rate_change, kRateChange) : kRateChange;
}

ScalingLimits planScalingLimits(const GroupMotion* groups, int count, double k) {
  constexpr double kMargin = 0.9;
  double rate = TimeScaling::kMaxRate, rate_change = kMaxRateChange;
  for (int g = 0; g < count; ++g) {
    const GroupMotion& m = groups[g];
    if (!(m.velocity > 1e-9)) continue;  // standing still: k may change at any rate
    const double spare = std::max(0.0, m.acceleration_limit - m.acceleration * k * k);
    rate = std::min(rate, kMargin * spare / m.velocity);
    rate_change = std::min(rate_change, kMargin * m.jerk_reserve / m.velocity);
  }
  return {std::clamp(rate, TimeScaling::kMinRate, TimeScaling::kMaxRate),
          std::clamp(rate_change, TimeScaling::kRateChange, kMaxRateChange)};
}

void TimeScaling::step(double dt) {
  const double error = target_ - value_;
  const double max_change = max_rate_change_ * dt;
  if (std::abs(error) < 1e-12 && std::abs(rate_) <= max_change) {
    value_ = target_;
    rate_ = 0;
    return;
  }
  const double braking = max_change * (std::sqrt(0.25 + 2 * std::abs(error) / (dt * max_change)) - 0.5);
  const double desired = std::copysign(std::min(max_rate_, braking), error);
  rate_ += std::clamp(desired - rate_, -max_change, max_change);
  const double next = value_ + rate_ * dt;
  const bool passed = (error > 0 && next >= target_) || (error < 0 && next <= target_);
  if (passed) {
    value_ = target_;
    rate_ = 0;
  } else {
    value_ = std::clamp(next, 0.0, 1.0);
  }
}

}  // namespace xmate::teach
