// SPDX-License-Identifier: Apache-2.0
// Closed-form IK of the 6-axis xMate arms (xMate 3/7): no shoulder offset, upper arm a2, forearm
// d4, spherical wrist; 8 branches (shoulder, elbow, wrist). docs/kinematics.md, "6-axis".
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/ik_branches.h"

namespace xmate::model {

// The up to 8 solutions reaching `flange`. Returns kBeyondReach, kTooClose or kSingular (wrist
// centre on the joint-1 axis, arm stretched or folded) when there are none, else kOk with out filled.
IkStatus sixAxisCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, const JointVector& q_init,
                           IkCandidates& out);

}  // namespace xmate::model
