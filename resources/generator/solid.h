// SPDX-License-Identifier: Apache-2.0
// The solids a link shell is made of: solids of revolution, each a profile curve in the (r, z)
// half-plane turned about its own z axis and placed in a link frame. The mesher and the
// mass-property code read the same solids, so the inertia belongs to the shape that is drawn.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace xmate::robotgen {

// One piece of a profile curve in the (r, z) half-plane: a straight line or a circular arc.
struct ProfilePiece {
  enum class Kind { Line, Arc };
  Kind kind = Kind::Line;
  Eigen::Vector2d from = Eigen::Vector2d::Zero();    // Line: start (r, z)
  Eigen::Vector2d to = Eigen::Vector2d::Zero();      // Line: end (r, z)
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // Arc: centre (r, z)
  double radius = 0;                                 // Arc: radius
  double angle_from = 0, angle_to = 0;               // Arc: angles from +r towards +z, rad
  int mesh_steps = 1;                                // straight pieces the mesher cuts it into
};

// A closed profile: starts on the axis at the bottom (r = 0), runs outwards, up and back to the
// axis at the top, counter-clockwise in the (r, z) plane (the axis closes it).
using Profile = std::vector<ProfilePiece>;

struct Solid {
  std::string what;  // "joint 2 housing", for the URDF comment and error messages
  Profile profile;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // solid frame (z = axis) -> link frame
};

// Point of a piece at parameter t in [0, 1] and its derivative d(r, z)/dt.
Eigen::Vector2d piecePoint(const ProfilePiece& piece, double t);
Eigen::Vector2d pieceTangent(const ProfilePiece& piece, double t);

// A cylinder of `radius` from z0 to z1 whose two rims are rounded with `fillet` (0 = sharp).
Profile roundedCylinder(double radius, double z0, double z1, double fillet);

// A capsule: cylinder of `radius` from z = 0 to z = length with a hemisphere on each end.
Profile capsule(double radius, double length);

// A frame at `origin` whose z axis points along `axis` (any length > 0). The x axis is a fixed
// function of `axis`, so the output is deterministic.
Eigen::Isometry3d axisFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis);

}  // namespace xmate::robotgen
