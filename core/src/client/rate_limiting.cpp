// SPDX-License-Identifier: Apache-2.0
// JointRateLimiter (xmate/rate_limiting.h): one joint at a time -- the velocity wanted (follow the
// targets, close a gap no faster than a stop allows), then jerk, acceleration and velocity bounds.
#include <xmate/rate_limiting.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/robot_spec.h"

namespace xmate {
namespace {

constexpr double kCycle = 0.001;  // s: one command per controller cycle

// Braking uses this share of the acceleration bound; the rest absorbs the jerk-limited ramps.
constexpr double kBrakingShare = 0.8;
// The loops that pull the command back onto the targets after a jump, each well inside the next
// (position, velocity, acceleration; 1/s), so the command settles without ringing.
constexpr double kPositionGain = 15;
constexpr double kVelocityGain = 60;
constexpr double kAccelerationGain = 240;

// The fastest speed from which a stop within `distance` is possible with acceleration a and jerk j
// (stopping distance v^2 / 2a + v a / 2j, solved for v).
double brakingSpeed(double distance, double a, double j) {
  const double c = a * a / (2 * j);
  return -c + std::sqrt(c * c + 2 * a * distance);
}

}  // namespace

JointRateLimits ratedJointRateLimits(XmateType type, double share) {
  if (!(share > 0 && share <= 1))
    throw std::invalid_argument("ratedJointRateLimits: share = " + std::to_string(share) +
                                " is not in (0, 1]; it scales the model's rated joint limits");
  const model::RobotSpec& spec = model::robotSpec(type);
  JointRateLimits limits;
  for (int i = 0; i < spec.dof; ++i) {
    limits.velocity[size_t(i)] = share * spec.dq_max[size_t(i)];
    limits.acceleration[size_t(i)] = share * spec.ddq_max[size_t(i)];
    limits.jerk[size_t(i)] = share * spec.jerk_max[size_t(i)];
  }
  return limits;
}

std::array<double, 7> JointRateLimiter::limit(const std::array<double, 7>& desired, const RCI::robot::RobotState& state) {
  std::array<double, 7> out = state.q_c;
  for (size_t i = 0; i < 7; ++i) {
    const double v_max = limits_.velocity[i], a_max = limits_.acceleration[i], j_max = limits_.jerk[i];
    if (!(v_max > 0 && a_max > 0 && j_max > 0)) continue;  // held where the controller's command is
    // How the targets move (differences of the targets, each within its bound): on a stream
    // within the bounds the command follows them exactly.
    // The first targets continue the controller's last command.
    Target& t = targets_[i];
    if (!t.known) t = {state.q_c[i], state.dq_c[i], state.ddq_c[i], true};
    const double v_t = std::clamp((desired[i] - t.q) / kCycle, -v_max, v_max);
    const double a_t = std::clamp((v_t - t.v) / kCycle, -a_max, a_max);
    const double j_t = std::clamp((a_t - t.a) / kCycle, -j_max, j_max);
    t = {desired[i], v_t, a_t, true};
    // Off the targets (a jump): back onto them, the gap closed no faster than a stop allows.
    // Where the command would go on the targets' jerk alone; on the targets that is the target.
    const double q = state.q_c[i], v = state.dq_c[i], a = state.ddq_c[i];
    const double a_next = a + kCycle * j_t, v_next = v + kCycle * a_next, q_next = q + kCycle * v_next;
    const double gap = desired[i] - q_next;
    const double closing = std::min(kPositionGain * std::abs(gap), brakingSpeed(std::abs(gap), kBrakingShare * a_max, j_max));
    const double v_wanted = std::clamp(v_t + std::copysign(closing, gap), -v_max, v_max);
    const double a_wanted = std::clamp(a_t + kVelocityGain * (v_wanted - v_next), -a_max, a_max);
    const double jerk = std::clamp(j_t + kAccelerationGain * (a_wanted - a_next), -j_max, j_max);
    // Acceleration: near the velocity bound only as much as a jerk-limited ramp back to zero
    // acceleration allows without passing it.
    const double ramp = j_max / a_max;
    const double upper = std::min(a_max, ramp * (v_max - v)), lower = std::max(-a_max, ramp * (-v_max - v));
    const double acceleration = std::clamp(a + jerk * kCycle, std::min(lower, upper), std::max(lower, upper));
    const double velocity = std::clamp(v + acceleration * kCycle, -v_max, v_max);
    out[i] = q + velocity * kCycle;
  }
  return out;
}

}  // namespace xmate
