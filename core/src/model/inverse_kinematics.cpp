// SPDX-License-Identifier: Apache-2.0
// Entry point of the closed-form IK: input checks, TCP -> flange, the model's solver, the choice.
#include "model/inverse_kinematics.h"

#include <cmath>

#include "model/ik_branches.h"
#include "model/ik_six_axis.h"
#include "model/ik_srs.h"

namespace xmate::model {
namespace {

constexpr double kRigidTolerance = 1e-6;

}  // namespace

const char* ikStatusText(IkStatus status) {
  switch (status) {
    case IkStatus::kOk: return "solved";
    case IkStatus::kBeyondReach: return "target beyond the arm's reach";
    case IkStatus::kTooClose: return "target too close to the shoulder for the elbow to fold that far";
    case IkStatus::kInvalidPose: return "pose is not a rigid transform (or q_init/psi not finite)";
    case IkStatus::kArmJointTooFast: return "an arm joint would exceed its rated speed from q_init";
    case IkStatus::kWristJointTooFast: return "a wrist joint would exceed its rated speed from q_init";
    case IkStatus::kAboveSoftLimit: return "every solution is above a joint's upper soft limit";
    case IkStatus::kBelowSoftLimit: return "every solution is below a joint's lower soft limit";
    case IkStatus::kSingular: return "target is at a singularity";
  }
  return "unknown IK status";
}

bool isRigidTransform(const Eigen::Matrix4d& pose) {
  if (!pose.allFinite()) return false;
  const Eigen::RowVector4d last_row(0, 0, 0, 1);
  if ((pose.row(3) - last_row).cwiseAbs().maxCoeff() > kRigidTolerance) return false;
  const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > kRigidTolerance) return false;
  return r.determinant() > 0;
}

IkStatus inverseKinematics(const ArmModel& arm, const Eigen::Matrix4d& tcp_pose, double psi,
                           const JointVector& q_init, JointVector& q_out) {
  const bool psi_used = arm.dof == 7;
  if (!isRigidTransform(tcp_pose) || !q_init.head(arm.dof).allFinite() || (psi_used && !std::isfinite(psi)))
    return IkStatus::kInvalidPose;
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.linear() = tcp_pose.topLeftCorner<3, 3>();
  tcp.translation() = tcp_pose.topRightCorner<3, 1>();
  const Eigen::Isometry3d flange = tcp * arm.tool_inverse;

  IkCandidates candidates;
  const IkStatus status = psi_used ? srsCandidates(arm, flange, psi, q_init, candidates)
                                   : sixAxisCandidates(arm, flange, q_init, candidates);
  if (status != IkStatus::kOk) return status;
  return chooseSolution(arm, candidates, q_init, q_out);
}

double armAngle(const ArmModel& arm, const JointVector& q) { return arm.dof == 7 ? srsArmAngle(arm, q) : 0.0; }

}  // namespace xmate::model
