// SPDX-License-Identifier: Apache-2.0
// How the simulated controller turns targets into a smooth joint reference for its servo: the
// reference track (position at the start and end of each 1 ms cycle, velocity, acceleration), the
// stop ramp used for every stop (error, guard stop, StopMove, end of a non-position motion), the
// smooth clamp of auto_limit, and the blend that rejoins commands after lost ones. Allocation-free.
#pragma once

#include <array>

#include "model/arm_model.h"

namespace xmate::sim {

using model::JointVector;

// The joint reference over one cycle: from `previous` (start) to `current` (end), with the velocity
// and acceleration of that step (finite differences of successive positions).
struct JointTrack {
  JointVector previous = JointVector::Zero();
  JointVector current = JointVector::Zero();
  JointVector velocity = JointVector::Zero();
  JointVector acceleration = JointVector::Zero();

  // Start at q moving with velocity dq (no acceleration).
  void resetAt(const JointVector& q, const JointVector& dq, double dt) {
    current = q;
    previous = q - dq * dt;
    velocity = dq;
    acceleration.setZero();
  }
  // The next cycle ends at q.
  void advanceTo(const JointVector& q, double dt) {
    const JointVector v = (q - current) / dt;
    acceleration = (v - velocity) / dt;
    velocity = v;
    previous = current;
    current = q;
  }
  // Position at fraction s in [0, 1] of the cycle.
  JointVector at(double s) const { return previous + s * (current - previous); }
};

// A stop: each joint's velocity falls to zero at its own deceleration, then the ramp stands still.
struct StopRamp {
  bool active = false;
  JointVector q = JointVector::Zero();
  JointVector v = JointVector::Zero();

  void start(const JointVector& q0, const JointVector& v0) {
    active = true;
    q = q0;
    v = v0;
  }
  // Advances one cycle; clears `active` once every joint stands still.
  void step(const JointVector& deceleration, double dt);
};

// auto_limit: the servo reference follows the (filtered) target, but never passes the soft limits
// and approaches them no faster than the speed from which `deceleration` still stops at them
// (v <= sqrt(2 a d), in its discrete form). Once held back, a joint catches up with its target again
// with acceleration bounded by `deceleration` (a saturated, critically damped tracker), so leaving
// the limit is as smooth as arriving.
class SoftLimitClamp {
 public:
  // Start following `target` (no joint held back).
  void reset(const JointVector& target);
  // The reference at the end of the next cycle, given the track so far and the new target.
  JointVector next(const JointTrack& track, const JointVector& target, const JointVector& lower,
                   const JointVector& upper, const JointVector& deceleration, int dof, double dt);

 private:
  std::array<bool, model::kMaxDof> held_{};
  JointVector previous_target_ = JointVector::Zero();
};

// Commands that arrive again after lost ones: while they were lost the target ran on along the
// extrapolation, and the client's commands are somewhere else by then (the plan went on, or the
// client never saw the loss). Stepping onto them would reach the servo as a jolt. Instead the
// target keeps an offset (extrapolation - command, position and velocity) that decays as a
// critically damped second-order system with its acceleration capped. Joint space.
// docs/simulator_controller.md, "Lost commands".
struct RejoinBlend {
  static constexpr double kOmega = 20.0;               // rad/s: the offset is mostly gone after ~0.3 s
  static constexpr double kAccelerationShare = 0.25;  // of the rated acceleration, at most
  JointVector offset = JointVector::Zero();
  JointVector rate = JointVector::Zero();
  bool active = false;

  void clear() {
    offset.setZero();
    rate.setZero();
    active = false;
  }
  // Adds to the offset's position and velocity (the first command after a gap, then the next one).
  void add(const JointVector& position, const JointVector& velocity) {
    offset += position;
    rate += velocity;
    active = true;
  }
  // Advances one cycle, the offset's acceleration within kAccelerationShare of `rated_acceleration`;
  // clears `active` once the offset is below any tolerance.
  void step(const JointVector& rated_acceleration, double dt);
};

}  // namespace xmate::sim
