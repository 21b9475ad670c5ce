// SPDX-License-Identifier: Apache-2.0
// The step every closed-form IK here ends with: from the raw branch solutions of one request to
// the one answer (2*pi equivalents, soft limits, nearest to q_init, rated-speed check).
#pragma once

#include <array>

#include "model/arm_model.h"
#include "model/euler_zyz.h"
#include "model/inverse_kinematics.h"

namespace xmate::model {

struct IkCandidate {
  JointVector q = JointVector::Zero();  // raw angles, any 2*pi representative
  bool singular = false;                // within kIkSingularTolerance of a singularity
};

// The up to 8 branch solutions of one request.
struct IkCandidates {
  std::array<IkCandidate, 8> items;
  int count = 0;
};

// The vector from the shoulder (joint 2's axis on joint 1's axis) to the wrist centre (where the
// wrist axes meet) for a flange pose, in the base frame: the start of the xMate closed-form IKs.
Eigen::Vector3d shoulderToWrist(const ArmGeometry& g, const Eigen::Isometry3d& flange);

// Sets joints first .. first + 2 of q to a Z-Y-Z solution of z: branch 0 is (a, b, c), branch 1
// is (a + pi, -b, c + pi).
void setZyzBranch(JointVector& q, int first, const ZyzAngles& z, int branch);

// Adds q with both wrist branches (setZyzBranch at wrist_joint) to out: two candidates.
void addWristBranches(IkCandidates& out, JointVector q, int wrist_joint, const ZyzAngles& wrist, bool singular);

// Z-Y-Z angles of r; when sin(b) < kIkSingularTolerance, sets `singular` and keeps joint a at
// a_preferred (the split the decomposition cannot determine).
ZyzAngles zyzForIk(const Eigen::Matrix3d& r, double a_preferred, bool& singular);

// Moves each joint of q by the multiple of 2*pi nearest q_init that keeps it inside the arm's soft
// limits (where none does, the representative nearest q_init) into placed; true when every joint
// is inside. Real-time safe.
bool placeWithinLimits(const ArmModel& arm, const JointVector& q, const JointVector& q_init, JointVector& placed);

// Picks the solution nearest q_init among those within the soft limits (or, if none is, the
// nearest of all, to report its first limit violation), then applies the singularity and
// rated-speed checks. Writes q_out only on kOk.
IkStatus chooseSolution(const ArmModel& arm, const IkCandidates& candidates, const JointVector& q_init,
                        JointVector& q_out);

}  // namespace xmate::model
