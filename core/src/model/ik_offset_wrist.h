// SPDX-License-Identifier: Apache-2.0
// Closed-form IK of 6-axis ortho-parallel arms with a shoulder offset, an elbow offset and a
// spherical wrist (the KUKA KR 6 R900 sixx and KR 16-2; the "OPW" geometry): 8 branches (shoulder
// front/back, elbow up/down, wrist flip). docs/kinematics.md, "Offset wrist (KUKA)".
#pragma once

#include <Eigen/Geometry>

#include "model/arm_model.h"
#include "model/ik_branches.h"

namespace xmate::model {

// The up to 8 solutions reaching `flange` (raw angles, any 2*pi representative), appended to out.
// Returns kSingular when the wrist centre is on the J1 axis (J1 undetermined), kBeyondReach or
// kTooClose when neither shoulder branch reaches the wrist centre (the front branch's reason),
// else kOk. Candidates at a stretched or folded elbow or with J4/J6 coaxial are marked singular;
// in the coaxial case J4 keeps its value in q_init. Any thread; real-time safe (no allocation).
IkStatus offsetWristCandidates(const ArmModel& arm, const Eigen::Isometry3d& flange, const JointVector& q_init,
                               IkCandidates& out);

}  // namespace xmate::model
