// SPDX-License-Identifier: Apache-2.0
// Lathe meshing of profiles and assembly of shell meshes (see triangle_mesh.h).
#include "generator/triangle_mesh.h"

#include <cmath>
#include <stdexcept>

namespace xmate::robotgen {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOnAxis = 1e-12;  // m: a profile end closer to the axis is a pole

}  // namespace

std::vector<Eigen::Vector2d> sampleProfile(const Profile& profile) {
  std::vector<Eigen::Vector2d> points;
  if (profile.empty()) return points;
  points.push_back(piecePoint(profile.front(), 0));
  for (const ProfilePiece& piece : profile) {
    for (int k = 1; k <= piece.mesh_steps; ++k) {
      const Eigen::Vector2d p = piecePoint(piece, double(k) / piece.mesh_steps);
      if ((p - points.back()).norm() > kOnAxis) points.push_back(p);
    }
  }
  return points;
}

TriangleMesh latheMesh(const Profile& profile, int segments) {
  const std::vector<Eigen::Vector2d> points = sampleProfile(profile);
  if (points.size() < 3 || std::abs(points.front().x()) > kOnAxis || std::abs(points.back().x()) > kOnAxis)
    throw std::invalid_argument("latheMesh: a profile must start and end on the axis (r = 0)");
  if (segments < 3) throw std::invalid_argument("latheMesh: needs at least 3 segments");

  // Vertex layout: bottom pole, rings 1..n-2 (segments each), top pole.
  TriangleMesh mesh;
  const int rings = int(points.size()) - 2;
  mesh.vertices.emplace_back(0, 0, points.front().y());
  for (int i = 1; i <= rings; ++i) {
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * kPi * k / segments;
      mesh.vertices.emplace_back(points[i].x() * std::cos(phi), points[i].x() * std::sin(phi), points[i].y());
    }
  }
  const int top = int(mesh.vertices.size());
  mesh.vertices.emplace_back(0, 0, points.back().y());

  // Vertex of profile point i at segment k (poles have one vertex for all k).
  auto at = [&](int i, int k) {
    if (i == 0) return 0;
    if (i == rings + 1) return top;
    return 1 + (i - 1) * segments + k % segments;
  };
  // Between profile points i and i+1: quads (a, b, c, d) with a, b on i, counter-clockwise
  // from outside because the profile runs counter-clockwise in the (r, z) plane.
  for (int i = 0; i <= rings; ++i) {
    for (int k = 0; k < segments; ++k) {
      const int a = at(i, k), b = at(i, k + 1), c = at(i + 1, k + 1), d = at(i + 1, k);
      if (i == 0) {
        mesh.triangles.push_back({a, c, d});
      } else if (i == rings) {
        mesh.triangles.push_back({a, b, c});
      } else {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      }
    }
  }
  return mesh;
}

void appendMesh(TriangleMesh& into, const TriangleMesh& part, const Eigen::Isometry3d& pose) {
  const int offset = int(into.vertices.size());
  for (const Eigen::Vector3d& v : part.vertices) into.vertices.push_back(pose * v);
  for (const auto& t : part.triangles) into.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

TriangleMesh shellMesh(const std::vector<Solid>& solids) {
  TriangleMesh mesh;
  for (const Solid& s : solids) appendMesh(mesh, latheMesh(s.profile), s.pose);
  return mesh;
}

}  // namespace xmate::robotgen
