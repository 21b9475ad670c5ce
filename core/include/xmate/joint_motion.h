// SPDX-License-Identifier: Apache-2.0
// Jerk-limited joint-space S-curve from rest to rest, all joints arriving together (docs/api.md,
// "JointMotionGenerator and CartMotionGenerator"). Limits are the model's joint velocity, acceleration
// and jerk limits (docs/robot_models.md, "Limits") times speed_ratio.
#pragma once

#include <array>

#include <xmate/cart_motion.h>  // planning::DoubleSProfile
#include <xmate/types.h>

namespace xmate {

// Threads: one generator belongs to one thread at a time. The constructor and GetTime may be called
// anywhere; calculateSynchronizedValues_joint, calculateDesiredValues_joint and
// calculateDerivatives_joint are real-time safe (no allocation, no lock, no system call) for valid
// arguments, so a Control() callback may call them every cycle -- only a refused argument throws.
class JointMotionGenerator {
 public:
  // speed_ratio in (0, 1]; throws std::invalid_argument outside it, for a non-finite goal or a
  // goal outside the model's joint range.
  // type selects the joint limits (XMATE7_PRO/XMATE3_PRO share them; 6-axis models ignore q_goal[6]).
  JointMotionGenerator(double speed_ratio, const std::array<double, 7>& q_goal, XmateType type = XMATE7_PRO);

  // Plans from q_start. Cheap to call again with the same q_start (vendor programs call it every
  // cycle): the plan is only recomputed when q_start changes. Throws std::invalid_argument for a
  // non-finite q_start or one outside the joint range.
  void calculateSynchronizedValues_joint(const std::array<double, 7>& q_start);

  // Writes the offset from q_start at time t (s) into delta_q; returns true once t >= GetTime(),
  // when delta_q is exactly q_goal - q_start. Throws xmate::MotionException before the first
  // calculateSynchronizedValues_joint, std::invalid_argument for a NaN t.
  bool calculateDesiredValues_joint(double t, std::array<double, 7>& delta_q) const;

  // Duration of the planned motion in seconds (0 before planning or for a zero move).
  double GetTime() const;

  // Extension: velocity and acceleration of the plan at time t (rad/s, rad/s^2); zero outside
  // [0, GetTime()]. Same preconditions as calculateDesiredValues_joint.
  void calculateDerivatives_joint(double t, std::array<double, 7>& dq, std::array<double, 7>& ddq) const;

 private:
  // Owned by core/src/planning/joint_motion.cpp; see there.
  double speed_ratio_;
  std::array<double, 7> q_goal_;
  XmateType type_;
  bool planned_ = false;
  std::array<double, 7> q_start_{};
  std::array<double, 7> delta_{};     // q_goal - q_start (0 for joints the model does not have)
  planning::DoubleSProfile profile_;  // the common normalised profile s(t): 0 -> 1
};

}  // namespace xmate
