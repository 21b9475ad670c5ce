// SPDX-License-Identifier: Apache-2.0
// Entry point of the closed-form IK: input checks, TCP -> flange, the model's solver, the choice.
#include "model/inverse_kinematics.h"

#include <cmath>

#include "model/ik_branches.h"
#include "model/ik_offset_wrist.h"
#include "model/ik_six_axis.h"
#include "model/ik_srs.h"

namespace xmate::model {
namespace {

constexpr double kRigidTolerance = 1e-6;

// Input checks, TCP -> flange and the arm's closed-form solver: the raw branch solutions.
IkStatus candidatesFor(const ArmModel& arm, const Eigen::Matrix4d& tcp_pose, double psi, const JointVector& q_init,
                       IkCandidates& candidates) {
  const bool psi_used = arm.geometry.kind == IkGeometry::kSrs;
  if (!isRigidTransform(tcp_pose) || !q_init.head(arm.dof).allFinite() || (psi_used && !std::isfinite(psi)))
    return IkStatus::kInvalidPose;
  Eigen::Isometry3d tcp = Eigen::Isometry3d::Identity();
  tcp.linear() = tcp_pose.topLeftCorner<3, 3>();
  tcp.translation() = tcp_pose.topRightCorner<3, 1>();
  const Eigen::Isometry3d flange = tcp * arm.tool_inverse;
  switch (arm.geometry.kind) {
    case IkGeometry::kSrs: return srsCandidates(arm, flange, psi, q_init, candidates);
    case IkGeometry::kSixAxis: return sixAxisCandidates(arm, flange, q_init, candidates);
    case IkGeometry::kOffsetWrist: return offsetWristCandidates(arm, flange, q_init, candidates);
  }
  return IkStatus::kSingular;
}

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
  IkCandidates candidates;
  const IkStatus status = candidatesFor(arm, tcp_pose, psi, q_init, candidates);
  if (status != IkStatus::kOk) return status;
  return chooseSolution(arm, candidates, q_init, q_out);
}

IkStatus inverseKinematicsBranches(const ArmModel& arm, const Eigen::Matrix4d& tcp_pose, double psi,
                                   const JointVector& q_init, IkBranchSolutions& out) {
  out.count = 0;
  IkCandidates candidates;
  const IkStatus status = candidatesFor(arm, tcp_pose, psi, q_init, candidates);
  if (status != IkStatus::kOk) return status;
  if (candidates.count == 0) return IkStatus::kSingular;
  for (int k = 0; k < candidates.count; ++k) {
    IkBranchSolution& s = out.items[out.count++];
    s.within_limits = placeWithinLimits(arm, candidates.items[k].q, q_init, s.q);
    s.singular = candidates.items[k].singular;
  }
  return IkStatus::kOk;
}

double armAngle(const ArmModel& arm, const JointVector& q) {
  return arm.geometry.kind == IkGeometry::kSrs ? srsArmAngle(arm, q) : 0.0;
}

}  // namespace xmate::model
