// SPDX-License-Identifier: Apache-2.0
// Edge topology, welding and tetrahedron-method mass properties (see mesh_checks.h).
#include "mesh_checks.h"

#include <map>
#include <utility>

#include <Eigen/Geometry>

namespace rci_test {

std::string edgeProblem(const IndexedMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;  // (from, to) -> count
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const int back = reverse == directed.end() ? 0 : reverse->second;
    if (count != 1 || back != 1)
      return "edge " + std::to_string(edge.first) + "->" + std::to_string(edge.second) + " used " +
             std::to_string(count) + " time(s) this way and " + std::to_string(back) + " the other way";
  }
  return {};
}

IndexedMesh weld(const std::vector<std::array<Eigen::Vector3d, 3>>& soup) {
  IndexedMesh mesh;
  std::map<std::array<double, 3>, int> index;
  for (const auto& tri : soup) {
    std::array<int, 3> t{};
    for (int v = 0; v < 3; ++v) {
      const std::array<double, 3> key{tri[v].x(), tri[v].y(), tri[v].z()};
      const auto [it, inserted] = index.emplace(key, int(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back(tri[v]);
      t[v] = it->second;
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

MeshMassProperties meshMassProperties(const IndexedMesh& mesh) {
  // Each triangle and the origin span a tetrahedron; signed sums over them give the solid's
  // integrals (the origin's contributions cancel for a closed surface).
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // integral of x x^T dV about the origin
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const double v = a.dot(b.cross(c)) / 6;
    const Eigen::Vector3d s = a + b + c;
    volume += v;
    first += v * s / 4;
    second += v / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  MeshMassProperties out;
  out.volume = volume;
  out.centroid = first / volume;
  const Eigen::Matrix3d central = second - volume * out.centroid * out.centroid.transpose();
  out.inertia_per_density = central.trace() * Eigen::Matrix3d::Identity() - central;
  return out;
}

}  // namespace rci_test
