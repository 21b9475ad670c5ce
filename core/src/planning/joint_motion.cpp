// SPDX-License-Identifier: Apache-2.0
// JointMotionGenerator (xmate/joint_motion.h): the vendor API around planning::JointLine -- every
// joint follows q_i(t) = q_start_i + delta_i s(t) with one normalised double-S profile s: 0 -> 1, so
// all joints move on a straight line in joint space, start and stop together, and none exceeds its
// own limits (docs/planning.md).
#include <xmate/joint_motion.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <xmate/exception.h>

#include "model/robot_spec.h"
#include "planning/double_s.h"
#include "planning/joint_line.h"

namespace xmate {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

void requireSpeedRatio(double speed_ratio) {
  if (std::isfinite(speed_ratio) && speed_ratio > 0 && speed_ratio <= 1) return;
  std::ostringstream msg;
  msg << "JointMotionGenerator: speed_ratio = " << speed_ratio << " is outside (0, 1]; pass e.g. 0.2";
  throw std::invalid_argument(msg.str());
}

// Throws std::invalid_argument unless every joint the model has is finite and within its range.
void requireInRange(const std::array<double, 7>& q, const model::RobotSpec& spec, const char* what) {
  for (int i = 0; i < spec.dof; ++i) {
    if (std::isfinite(q[i]) && q[i] >= spec.q_min[i] && q[i] <= spec.q_max[i]) continue;
    std::ostringstream msg;
    msg << "JointMotionGenerator: " << what << "[" << i << "] = " << q[i] << " rad is outside joint " << i + 1
        << "'s range [" << spec.q_min[i] << ", " << spec.q_max[i] << "] rad (" << spec.q_min[i] * kRadToDeg
        << " .. " << spec.q_max[i] * kRadToDeg << " deg) of the " << spec.display_name
        << "; pass a finite value inside it";
    throw std::invalid_argument(msg.str());
  }
}

// A start may lie a little beyond a joint's range -- where a stop ramp or the operator's hand can
// leave a joint -- since every joint moves in a straight line towards the goal, which is inside.
constexpr double kStartBeyondRange = 0.2;  // rad

void requireUsableStart(const std::array<double, 7>& q, const model::RobotSpec& spec) {
  for (int i = 0; i < spec.dof; ++i) {
    if (std::isfinite(q[i]) && q[i] >= spec.q_min[i] - kStartBeyondRange && q[i] <= spec.q_max[i] + kStartBeyondRange)
      continue;
    std::ostringstream msg;
    msg << "JointMotionGenerator: q_start[" << i << "] = " << q[i] << " rad is not a finite value within 0.2 rad of joint "
        << i + 1 << "'s range [" << spec.q_min[i] << ", " << spec.q_max[i] << "] rad (" << spec.q_min[i] * kRadToDeg
        << " .. " << spec.q_max[i] * kRadToDeg << " deg) of the " << spec.display_name
        << "; pass the robot's joints (RobotState::q)";
    throw std::invalid_argument(msg.str());
  }
}

void requirePlanned(bool planned) {
  if (!planned)
    throw MotionException(
        "JointMotionGenerator: no plan yet; call calculateSynchronizedValues_joint(q_start) first");
}

void requireTime(double t) {
  if (std::isnan(t))
    throw std::invalid_argument(
        "JointMotionGenerator: time t is NaN; pass the time since the motion began, in s");
}

}  // namespace

JointMotionGenerator::JointMotionGenerator(double speed_ratio, const std::array<double, 7>& q_goal,
                                           XmateType type)
    : speed_ratio_(speed_ratio), q_goal_(q_goal), type_(type) {
  requireSpeedRatio(speed_ratio);
  requireInRange(q_goal, model::robotSpec(type), "q_goal");
}

void JointMotionGenerator::calculateSynchronizedValues_joint(const std::array<double, 7>& q_start) {
  if (planned_ && q_start == q_start_) return;  // vendor programs call this every cycle

  const model::RobotSpec& spec = model::robotSpec(type_);
  requireUsableStart(q_start, spec);
  const planning::JointLine line = planning::planJointLine(spec, q_start, q_goal_, speed_ratio_);
  profile_ = line.profile;
  delta_ = line.delta;
  q_start_ = q_start;
  planned_ = true;
}

bool JointMotionGenerator::calculateDesiredValues_joint(double t, std::array<double, 7>& delta_q) const {
  requirePlanned(planned_);
  requireTime(t);
  if (t >= profile_.duration) {
    delta_q = delta_;
    return true;
  }
  const double s = planning::sampleDoubleS(profile_, t).p;
  for (int i = 0; i < 7; ++i) delta_q[i] = delta_[i] * s;
  return false;
}

double JointMotionGenerator::GetTime() const { return planned_ ? profile_.duration : 0.0; }

void JointMotionGenerator::calculateDerivatives_joint(double t, std::array<double, 7>& dq,
                                                      std::array<double, 7>& ddq) const {
  requirePlanned(planned_);
  requireTime(t);
  const planning::DoubleSSample s = planning::sampleDoubleS(profile_, t);
  for (int i = 0; i < 7; ++i) {
    dq[i] = delta_[i] * s.v;
    ddq[i] = delta_[i] * s.a;
  }
}

}  // namespace xmate
