// SPDX-License-Identifier: Apache-2.0
// Geometry of the Cartesian paths of MOVEL (straight line) and MOVEC (circular arc from the start
// through a via point to the target): TCP position, orientation and arm angle psi as functions of
// one normalised path parameter u in [0, 1]. Timing is cartesian_trajectory.h's job.
#pragma once

#include <array>

#include <Eigen/Geometry>

namespace xmate::planning {

// A pose a path starts at, passes through or ends at: the TCP in the base frame and the arm angle.
struct PathPoint {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double psi = 0;  // rad; the 6-axis models have no arm angle: pass the same value everywhere
};

enum class PathShape { kLine, kArc };

struct CartesianPath {
  PathShape shape = PathShape::kLine;
  PathPoint start, target;  // returned verbatim at u = 0 and u = 1
  double length = 0;        // L: distance the TCP travels, m

  // Arc only: p(u) = centre + radius (cos(sweep u) e1 + sin(sweep u) e2), where e1 points from the
  // centre to the start and e2 = normal x e1, the normal oriented so that the arc reaches the via
  // point before the target.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
  double radius = 0;  // m
  double sweep = 0;   // rad, in (0, 2 pi)
  double via_u = 0;   // u at which the arc passes through the via point

  // Orientation (both shapes): R(u) = R_start * AngleAxis(rotation_angle * u, rotation_axis), the
  // shortest rotation from the start to the target orientation (quaternion slerp). The axis is in
  // the start's tool frame; the via point's orientation is not used.
  double rotation_angle = 0;  // theta, rad, in [0, pi]
  Eigen::Vector3d rotation_axis = Eigen::Vector3d::UnitZ();

  double psi_delta = 0;  // psi(u) = start.psi + psi_delta * u
};

// The path at one u, with the derivatives the timing needs.
struct PathState {
  Eigen::Vector3d position;        // m, base frame
  Eigen::Vector3d dposition_du;    // m
  Eigen::Vector3d d2position_du2;  // m (zero on a line; points at the centre on an arc)
  Eigen::Matrix3d rotation;        // TCP orientation in the base frame
  Eigen::Vector3d omega_du;        // angular velocity per unit du/dt, base frame (constant)
  double psi;                      // rad
};

// MOVEL: position linear from start to target, orientation by slerp, psi linear.
// Throws std::invalid_argument for a pose that is not a rigid transform or a non-finite psi.
CartesianPath makeLinePath(const PathPoint& start, const PathPoint& target);

// MOVEC: the circle through the three positions, travelled from start through via to target;
// orientation by slerp from start to target in step with the arc angle; psi linear.
// Throws xmate::MotionException when two positions are closer than 0.1 mm or the three are
// collinear (circumradius above 100 m, or the sine of a triangle angle below 1e-6), and
// std::invalid_argument as makeLinePath does.
CartesianPath makeArcPath(const PathPoint& start, const PathPoint& via, const PathPoint& target);

// The path at u, clamped to [0, 1]; u <= 0 and u >= 1 give the start and target poses exactly.
// Allocation-free.
PathState evaluatePath(const CartesianPath& path, double u);

// A path point from the RCI's row-major 4x4 pose (checked as in cartesian_pose.h) and psi.
PathPoint pathPoint(const std::array<double, 16>& row_major_pose, double psi, const char* what);

}  // namespace xmate::planning
