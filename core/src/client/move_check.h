// SPDX-License-Identifier: Apache-2.0
// What MOVEJ/MOVEL/MOVEC check before they move: that the caller's start matches where the robot
// is, and that a Cartesian path can be followed in joint space (every 1 ms sample reachable by IK,
// joint speeds, accelerations and jerks within the limits) -- slowing the whole move down when it
// is only too fast. Failures throw xmate::MotionException saying where and what to do.
#pragma once

#include <array>
#include <vector>

#include <xmate/model.h>
#include <xmate/rci_types.h>

#include "client/standstill.h"
#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "planning/cartesian_trajectory.h"

namespace xmate::client {

// How far the caller's start may be from the robot's actual position.
inline constexpr double kStartJointTolerance = 1e-3;      // rad
inline constexpr double kStartPositionTolerance = 1e-3;   // m
inline constexpr double kStartRotationTolerance = 1e-3;   // rad

// The share of the rated joint and Cartesian velocity, acceleration and jerk MOVEJ/MOVEL/MOVEC plan
// with at speed_ratio 1.0. The rest is the stall bridge's reserve (stall_bridge.h): after lost
// states -- up to the ~15 commands in a row a controller tolerates losing -- the command rejoins the
// plan without exceeding any rated limit (docs/reliability.md, "Lost states"). The teach executor
// plans at 0.8 (teach::kSpeedShare).
inline constexpr double kFullSpeedShare = 0.85;
// speed_ratio (0, 1] as the share of the rated limits a library motion plans with.
inline double planShare(double speed_ratio) { return speed_ratio * kFullSpeedShare; }

// Throws std::invalid_argument unless speed_ratio is in (0, 1].
void requireSpeedRatio(const char* call, double speed_ratio);

// Throws MotionException when q_start differs from q_actual by more than kStartJointTolerance (plus
// `moved`: how far the arm came to rest after the caller read its start, Connection::awaitStandstill).
void requireStartJoints(const char* call, const std::array<double, 7>& q_start, const std::array<double, 7>& q_actual,
                        int dof, const StandstillWait& moved = {});
// Throws MotionException when the start pose is more than 1 mm / 1e-3 rad (plus `moved`) from the actual one.
void requireStartPose(const char* call, const std::array<double, 16>& start, const std::array<double, 16>& actual,
                      const StandstillWait& moved = {});

// The worst ratios of a sampled joint trajectory to the limits (> 1: too fast), and where the
// largest of them occurs.
struct JointSweep {
  double velocity_ratio = 0;      // max |dq| / (dq_max * speed_ratio)
  double acceleration_ratio = 0;  // max |ddq| / (ddq_max * kFullSpeedShare)
  double jerk_ratio = 0;          // max |dddq| / (jerk_max * kFullSpeedShare)
  double worst() const;           // the largest of the three
  double worst_time = 0;          // s since the start of the move
  int worst_joint = 0;            // 0-based
  std::array<double, 3> worst_tcp{};  // TCP position there, m
};

// A move is re-timed at most this much slower than asked before it counts as passing too close to
// a singular pose.
inline constexpr double kMaxSlowdown = 20.0;

// Samples `trajectory` every 1 ms from q_start with IK (q_init = the previous sample) and measures
// the joint rates by finite differences. Throws MotionException at the first sample IK cannot
// reach (naming the fraction of the path, the time, the TCP position and the IK reason). With
// `joints`, also gives the joints every 1 ms from q_start to the end.
using JointSamples = std::vector<std::array<double, 7>>;
JointSweep sweepTrajectory(const char* call, const planning::CartesianTrajectory& trajectory,
                           const model::ArmKinematics& model, const std::array<double, 7>& q_start, double speed_ratio,
                           JointSamples* joints = nullptr);

// Times `path` at speed_ratio and, while the joint rates would exceed their limits, re-times it
// slower (at most kMaxSlowdown times). Throws MotionException when it is unreachable, or when it
// would need a slower timing than that (it passes too close to a singular pose), saying where.
// With `joints`, also gives the returned trajectory's joints every 1 ms (sweepTrajectory).
planning::CartesianTrajectory planWithinJointLimits(const char* call, const planning::CartesianPath& path,
                                                    double speed_ratio, const model::ArmKinematics& model,
                                                    const std::array<double, 7>& q_start,
                                                    JointSamples* joints = nullptr);

// "beyond the arm's reach", ... for an XmateModel::IkResult.
const char* ikFailureText(int code);

}  // namespace xmate::client
