// SPDX-License-Identifier: Apache-2.0
// JogRamp: each cycle the acceleration that would land exactly on the target velocity, limited by
// the jerk and acceleration bounds; the last step lands exactly (so the ramp ends exactly at rest).
#include "jog/ramp.h"

#include <algorithm>
#include <cmath>

namespace xmate::jog {

JogRamp::JogRamp(const RampLimits& limits, double dt) : limits_(limits), dt_(dt) {}

double JogRamp::step(double target_velocity) {
  const double target = std::clamp(target_velocity, -limits_.v_max, limits_.v_max);
  const double dt = dt_, j = limits_.j_max, jdt = j * dt;
  const double error = target - v_;
  // The acceleration that lands exactly on the target: this cycle at a, then back to 0 in steps of
  // j dt gains a dt + sign(a) (a^2 / 2j - |a| dt / 2) (exact for whole steps); solved for a.
  double ideal;
  if (std::abs(error) <= jdt * dt)
    ideal = error / dt;
  else
    ideal = std::copysign(j * (std::sqrt(dt * dt / 4 + 2 * std::abs(error) / j) - dt / 2), error);
  const double a = std::clamp(std::clamp(ideal, a_ - jdt, a_ + jdt), -limits_.a_max, limits_.a_max);
  if (a == ideal && std::abs(error) <= jdt * dt) {
    v_ = target;  // the landing step: exactly on the target (no rounding residue)
    a_ = a;
  } else {
    a_ = a;
    v_ += a * dt;
  }
  return v_ * dt;
}

double JogRamp::stoppingDistance() const {
  // The farthest point reached in the present direction of motion (a stop may end a hair behind it).
  const double direction = v_ != 0 ? v_ : a_;
  JogRamp copy = *this;
  double distance = 0, farthest = 0;
  for (int i = 0; i < 100000 && !copy.atRest(); ++i) {
    distance += copy.step(0);
    if ((direction > 0 && distance > farthest) || (direction < 0 && distance < farthest)) farthest = distance;
  }
  return farthest;
}

double JogRamp::stoppingTime() const {
  JogRamp copy = *this;
  int cycles = 0;
  while (cycles < 100000 && !copy.atRest()) {
    copy.step(0);
    ++cycles;
  }
  return cycles * dt_;
}

}  // namespace xmate::jog
