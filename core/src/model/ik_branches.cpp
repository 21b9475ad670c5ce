// SPDX-License-Identifier: Apache-2.0
// Branch bookkeeping and solution choice shared by the 7-axis, 6-axis and offset-wrist closed-form IK.
#include "model/ik_branches.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xmate::model {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
// Rounding slack when deciding whether an angle is inside a limit (rad).
constexpr double kLimitSlack = 1e-12;

// Where a joint ends up: theta + 2 pi k nearest `target` inside [lower, upper] (returns true), or,
// when no k puts it inside, the representative nearest `target` (returns false).
bool placeAngle(double theta, double target, double lower, double upper, double& out) {
  const double k_min = std::ceil((lower - kLimitSlack - theta) / kTwoPi);
  const double k_max = std::floor((upper + kLimitSlack - theta) / kTwoPi);
  const double k_nearest = std::round((target - theta) / kTwoPi);
  if (k_min <= k_max) {
    out = theta + kTwoPi * std::clamp(k_nearest, k_min, k_max);
    return true;
  }
  out = theta + kTwoPi * k_nearest;
  return false;
}

struct PlacedSolution {
  JointVector q = JointVector::Zero();
  int first_violation = -1;  // joint index, -1 if within all limits
  bool violation_above = false;
  double distance2 = std::numeric_limits<double>::infinity();
  bool singular = false;
};

PlacedSolution place(const ArmModel& arm, const IkCandidate& c, const JointVector& q_init) {
  PlacedSolution s;
  s.singular = c.singular;
  for (int i = 0; i < arm.dof; ++i) {
    const bool inside = placeAngle(c.q[i], q_init[i], arm.lower[i], arm.upper[i], s.q[i]);
    if (!inside && s.first_violation < 0) {
      s.first_violation = i;
      s.violation_above = s.q[i] > arm.upper[i];
    }
  }
  s.distance2 = (s.q - q_init).head(arm.dof).squaredNorm();
  return s;
}

IkStatus speedCheck(const ArmModel& arm, const JointVector& q, const JointVector& q_init) {
  if (arm.speed_check_interval <= 0) return IkStatus::kOk;
  bool wrist_too_fast = false;
  for (int i = 0; i < arm.dof; ++i) {
    if (std::abs(q[i] - q_init[i]) <= arm.max_velocity[i] * arm.speed_check_interval) continue;
    if (i < arm.arm_joint_count) return IkStatus::kArmJointTooFast;
    wrist_too_fast = true;
  }
  return wrist_too_fast ? IkStatus::kWristJointTooFast : IkStatus::kOk;
}

}  // namespace

bool placeWithinLimits(const ArmModel& arm, const JointVector& q, const JointVector& q_init, JointVector& placed) {
  const PlacedSolution s = place(arm, IkCandidate{q, false}, q_init);
  placed = s.q;
  return s.first_violation < 0;
}

ZyzAngles zyzForIk(const Eigen::Matrix3d& r, double a_preferred, bool& singular) {
  ZyzAngles z = zyzAngles(r);
  singular = z.sin_b < kIkSingularTolerance;
  if (singular) resolveDegenerateZyz(r, a_preferred, z);
  return z;
}

Eigen::Vector3d shoulderToWrist(const ArmGeometry& g, const Eigen::Isometry3d& flange) {
  const Eigen::Vector3d wrist = flange.translation() - g.wrist_to_flange * flange.linear().col(2);
  return wrist - Eigen::Vector3d(0, 0, g.base_to_shoulder);
}

void setZyzBranch(JointVector& q, int first, const ZyzAngles& z, int branch) {
  q[first] = z.a + branch * kPi;
  q[first + 1] = branch == 0 ? z.b : -z.b;
  q[first + 2] = z.c + branch * kPi;
}

void addWristBranches(IkCandidates& out, JointVector q, int wrist_joint, const ZyzAngles& wrist, bool singular) {
  for (int branch = 0; branch < 2; ++branch) {
    setZyzBranch(q, wrist_joint, wrist, branch);
    out.items[out.count++] = IkCandidate{q, singular};
  }
}

IkStatus chooseSolution(const ArmModel& arm, const IkCandidates& candidates, const JointVector& q_init,
                        JointVector& q_out) {
  if (candidates.count == 0) return IkStatus::kSingular;
  PlacedSolution best_valid, best_any;
  bool any_valid = false;
  for (int k = 0; k < candidates.count; ++k) {
    const PlacedSolution s = place(arm, candidates.items[k], q_init);
    if (k == 0 || s.distance2 < best_any.distance2) best_any = s;
    if (s.first_violation < 0 && (!any_valid || s.distance2 < best_valid.distance2)) {
      best_valid = s;
      any_valid = true;
    }
  }
  const PlacedSolution& chosen = any_valid ? best_valid : best_any;
  if (chosen.singular) return IkStatus::kSingular;
  if (!any_valid) return chosen.violation_above ? IkStatus::kAboveSoftLimit : IkStatus::kBelowSoftLimit;
  const IkStatus speed = speedCheck(arm, chosen.q, q_init);
  if (speed != IkStatus::kOk) return speed;
  q_out = chosen.q;
  return IkStatus::kOk;
}

}  // namespace xmate::model
