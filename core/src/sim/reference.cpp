// SPDX-License-Identifier: Apache-2.0
// Stop ramp and the auto_limit clamp (reference.h).
#include "sim/reference.h"

#include <algorithm>
#include <cmath>

namespace xmate::sim {

void StopRamp::step(const JointVector& deceleration, double dt) {
  bool moving = false;
  for (int i = 0; i < model::kMaxDof; ++i) {
    const double dv = deceleration[i] * dt;
    v[i] = std::abs(v[i]) <= dv ? 0.0 : v[i] - std::copysign(dv, v[i]);
    q[i] += v[i] * dt;
    moving = moving || v[i] != 0.0;
  }
  active = moving;
}

void RejoinBlend::step(const JointVector& rated_acceleration, double dt) {
  if (!active) return;
  const JointVector cap = kAccelerationShare * rated_acceleration;
  const JointVector wanted = -kOmega * kOmega * offset - 2.0 * kOmega * rate;
  rate += wanted.cwiseMax(-cap).cwiseMin(cap) * dt;
  offset += rate * dt;
  if (offset.cwiseAbs().maxCoeff() < 1e-12 && rate.cwiseAbs().maxCoeff() < 1e-10) clear();
}

namespace {

// The fastest speed (per cycle of dt) from which a sequence of speeds falling by a dt per cycle still
// stops within distance d: the discrete form of sqrt(2 a d), which it approaches for d >> a dt^2.
double brakingSpeed(double a, double d, double dt) {
  if (d <= 0 || a <= 0) return 0.0;
  const double step = a * dt;
  return step * (std::sqrt(0.25 + 2.0 * d / (step * dt)) - 0.5);
}

}  // namespace

void SoftLimitClamp::reset(const JointVector& target) {
  held_.fill(false);
  previous_target_ = target;
}

JointVector SoftLimitClamp::next(const JointTrack& track, const JointVector& target, const JointVector& lower,
                                 const JointVector& upper, const JointVector& deceleration, int dof, double dt) {
  constexpr double kCatchUpBandwidth = 20.0;  // rad/s
  constexpr double kCaughtUp = 1e-9;          // rad and rad/s: back on the target
  JointVector next = target;
  for (int i = 0; i < dof; ++i) {
    const double x = track.current[i], v = track.velocity[i];
    const double up_speed = brakingSpeed(deceleration[i], upper[i] - x, dt);
    const double down_speed = brakingSpeed(deceleration[i], x - lower[i], dt);
    const double target_velocity = (target[i] - previous_target_[i]) / dt;
    const double free_speed = (target[i] - x) / dt;
    if (!held_[i] && free_speed <= up_speed && free_speed >= -down_speed) continue;  // following freely
    held_[i] = true;
    const double w = kCatchUpBandwidth;
    const double a = std::clamp(w * w * (target[i] - x) + 2 * w * (target_velocity - v), -deceleration[i],
                                deceleration[i]);
    const double speed = std::clamp(v + a * dt, -down_speed, up_speed);
    next[i] = std::clamp(x + speed * dt, lower[i], upper[i]);
    if (std::abs(next[i] - target[i]) < kCaughtUp && std::abs(speed - target_velocity) < kCaughtUp * 1e3) {
      next[i] = target[i];
      held_[i] = false;
    }
  }
  previous_target_ = target;
  return next;
}

}  // namespace xmate::sim
