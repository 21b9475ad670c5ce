// SPDX-License-Identifier: Apache-2.0
// Target resolution (targets.h).
#include "teach/targets.h"

#include "planning/cartesian_pose.h"

namespace xmate::teach {

int jointGoal(const Target& target, const model::ArmKinematics& model, const std::array<double, 7>& q_now,
              std::array<double, 7>& q_goal) {
  if (target.has_q) {
    q_goal = target.q;
    return XmateModel::kIkOk;
  }
  const double psi = target.has_psi ? target.psi : model.GetPsi(q_now);
  return model.GetJointPos(target.pose, psi, q_now, q_goal);
}

planning::PathPoint cartesianPoint(const Target& target, const model::ArmKinematics& model, double psi_hold, const char* what) {
  if (target.has_pose) return planning::pathPoint(target.pose, target.has_psi ? target.psi : psi_hold, what);
  return planning::pathPoint(model.GetCartPose(target.q), model.GetPsi(target.q), what);
}

planning::CartesianPath cartesianPath(const Instruction& in, const model::ArmKinematics& model, const std::array<double, 7>& q_now) {
  const double psi_now = model.GetPsi(q_now);
  const planning::PathPoint start = planning::pathPoint(model.GetCartPose(q_now), psi_now, "the start pose");
  const planning::PathPoint end = cartesianPoint(in.target, model, psi_now, "target");
  if (in.type != InstructionType::kMoveC) return planning::makeLinePath(start, end);
  return planning::makeArcPath(start, cartesianPoint(in.via, model, psi_now, "via"), end);
}

}  // namespace xmate::teach
