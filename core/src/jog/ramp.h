// SPDX-License-Identifier: Apache-2.0
// JogRamp: the 1-D velocity profile of a jog -- velocity ramps toward a target with bounded
// acceleration and jerk (docs/robot_models.md, "Command rules": velocity continuous and
// differentiable), one 1 ms cycle at a time, on the real-time thread (no allocation, no Qt).
#pragma once

namespace xmate::jog {

struct RampLimits {
  double v_max = 0;  // |target velocity| is clamped to this (unit/s)
  double a_max = 0;  // unit/s^2
  double j_max = 0;  // unit/s^3
};

class JogRamp {
 public:
  explicit JogRamp(const RampLimits& limits, double dt = 0.001);
  // Advances one cycle toward target_velocity; returns the displacement of this cycle.
  double step(double target_velocity);
  double velocity() const { return v_; }
  double acceleration() const { return a_; }
  double maxVelocity() const { return limits_.v_max; }
  bool atRest() const { return v_ == 0 && a_ == 0; }
  // Signed distance to the farthest point still reached if the target became 0 now (the same
  // profile, simulated).
  double stoppingDistance() const;
  // Seconds until rest if the target became 0 now.
  double stoppingTime() const;

 private:
  RampLimits limits_;
  double dt_;
  double v_ = 0, a_ = 0;
};

}  // namespace xmate::jog
