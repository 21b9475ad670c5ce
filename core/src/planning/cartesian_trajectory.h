// SPDX-License-Identifier: Apache-2.0
// Timing of a Cartesian path (cartesian_path.h): one normalised double-S profile u: 0 -> 1 for the
// whole move, slowed so that the TCP's translation and rotation and the arm angle all stay within
// the Cartesian limits times speed_ratio; and sampling of pose, psi and their rates at a time t.
// Used by MOVEL/MOVEC in the client, by the simulator and by the teach executor.
#pragma once

#include <array>

#include <Eigen/Geometry>

#include "model/robot_spec.h"
#include "planning/cartesian_path.h"
#include "planning/double_s.h"

namespace xmate::planning {

struct CartesianTrajectory {
  CartesianPath path;
  DoubleSProfile timing;  // u(t) from 0 to 1 (distance 0 and duration 0 for a zero move)
};

// Times `path` with the given limits (default: the planner's, docs/planning.md) times speed_ratio.
// Throws std::invalid_argument for speed_ratio outside (0, 1].
CartesianTrajectory timePath(const CartesianPath& path, double speed_ratio,
                             const model::CartesianLimits& limits = model::plannerCartesianLimits());

// MOVEL and MOVEC in one call: makeLinePath / makeArcPath, then timePath with the planner's limits.
CartesianTrajectory planLine(double speed_ratio, const PathPoint& start, const PathPoint& target);
CartesianTrajectory planArc(double speed_ratio, const PathPoint& start, const PathPoint& via,
                            const PathPoint& target);

// Duration of the move in seconds.
double duration(const CartesianTrajectory& trajectory);

// The commanded TCP motion at one instant (base frame).
struct CartesianSample {
  Eigen::Isometry3d pose;
  double psi;                            // rad
  Eigen::Vector3d linear_velocity;       // m/s
  Eigen::Vector3d linear_acceleration;   // m/s^2
  Eigen::Vector3d angular_velocity;      // rad/s
  Eigen::Vector3d angular_acceleration;  // rad/s^2
  double psi_velocity, psi_acceleration;
  bool finished;  // t >= duration: the pose is exactly the target, all rates are zero
};

// The trajectory at time t (s since the start); t <= 0 gives the start pose at rest.
// Throws std::invalid_argument for a NaN t; otherwise allocation-free.
CartesianSample sampleTrajectory(const CartesianTrajectory& trajectory, double t);

// RobotState's toolTobase_vel_c / toolTobase_acc_c layout: [linear; angular].
std::array<double, 6> velocityOf(const CartesianSample& sample);
std::array<double, 6> accelerationOf(const CartesianSample& sample);

}  // namespace xmate::planning
