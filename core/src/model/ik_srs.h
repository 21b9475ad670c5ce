// SPDX-License-Identifier: Apache-2.0
// Closed-form IK of the 7-axis S-R-S arms (xMate Pro 3/7) parametrised by the arm angle psi,
// after Shimizu et al. 2008, derived for the xMate DH tables (docs/kinematics.md, "7-axis").
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/ik_branches.h"

namespace xmate::model {

// The up to 8 solutions (branches of joints 2, 4 and 6) reaching `flange` with arm angle psi.
// Returns kBeyondReach, kTooClose or kSingular (wrist centre on the joint-1 axis, arm stretched)
// when there are none, else kOk with out filled.
IkStatus srsCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, double psi, const JointVector& q_init,
                       IkCandidates& out);

// Arm angle of configuration q.
double srsArmAngle(const ArmModel& arm, const JointVector& q);

}  // namespace xmate::model
