// SPDX-License-Identifier: Apache-2.0
// Independent checks of triangle meshes for the description tests: edge topology (closed,
// consistently wound), and volume / centre / inertia by the tetrahedron method, which shares no
// code with the generator's profile integrals.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rci_test {

struct IndexedMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Empty when every edge is used by exactly two triangles, once in each direction (closed and
// consistently wound); otherwise a description of the first offending edge.
std::string edgeProblem(const IndexedMesh& mesh);

// Welds a triangle soup (three vertices per triangle) by exact position.
IndexedMesh weld(const std::vector<std::array<Eigen::Vector3d, 3>>& soup);

struct MeshMassProperties {
  double volume = 0;                                   // signed: > 0 when facing outwards
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero();  // about the centroid
};

MeshMassProperties meshMassProperties(const IndexedMesh& mesh);

}  // namespace rci_test
