// SPDX-License-Identifier: Apache-2.0
// Test helpers: analytic command profiles with known velocity, acceleration and jerk, to stream
// into the simulated controller (the planners are tested elsewhere; these are independent).
#pragma once

#include <algorithm>

namespace xmate::sim::test {

// Starts from rest: acceleration rises at `jerk` until `acceleration`, then stays there.
struct JerkRamp {
  double jerk;
  double acceleration;

  double riseTime() const { return acceleration / jerk; }
  double accelerationAt(double t) const { return std::min(jerk * t, acceleration); }
  double velocityAt(double t) const {
    const double t1 = std::min(t, riseTime());
    return 0.5 * jerk * t1 * t1 + acceleration * std::max(t - riseTime(), 0.0);
  }
  double positionAt(double t) const {
    const double t1 = std::min(t, riseTime());
    const double t2 = std::max(t - riseTime(), 0.0);
    return jerk * t1 * t1 * t1 / 6.0 + 0.5 * jerk * t1 * t1 * t2 + 0.5 * acceleration * t2 * t2;
  }
};

}  // namespace xmate::sim::test
