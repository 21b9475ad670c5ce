// SPDX-License-Identifier: Apache-2.0
// Indexed triangle meshes of the link shells: each solid of revolution becomes one closed,
// outward-facing surface (counter-clockwise seen from outside).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "generator/solid.h"

namespace xmate::robotgen {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // vertex indices, counter-clockwise from outside
};

// Segments around every circle.
inline constexpr int kCircleSegments = 40;

// The profile's points in order: piece start, then each piece cut into its mesh steps.
std::vector<Eigen::Vector2d> sampleProfile(const Profile& profile);

// The profile turned about z: a pole vertex at each end and one ring per inner profile point.
TriangleMesh latheMesh(const Profile& profile, int segments = kCircleSegments);

// Adds `part`, moved by `pose`, to `into` (the surfaces stay separate closed shells).
void appendMesh(TriangleMesh& into, const TriangleMesh& part, const Eigen::Isometry3d& pose);

// All solids of a shell in one mesh, in the link frame.
TriangleMesh shellMesh(const std::vector<Solid>& solids);

}  // namespace xmate::robotgen
