// SPDX-License-Identifier: Apache-2.0
// Profile pieces, the two profile shapes the shells use, and solid placement (see solid.h).
#include "generator/solid.h"

#include <cmath>
#include <stdexcept>

namespace xmate::robotgen {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Mesh steps per quarter circle: a capsule end is seen up close, a rim fillet is small.
constexpr int kCapStepsPerQuarter = 8;
constexpr int kFilletStepsPerQuarter = 4;

ProfilePiece line(Eigen::Vector2d from, Eigen::Vector2d to) {
  ProfilePiece p;
  p.kind = ProfilePiece::Kind::Line;
  p.from = from;
  p.to = to;
  return p;
}

ProfilePiece arc(Eigen::Vector2d centre, double radius, double angle_from, double angle_to, int steps) {
  ProfilePiece p;
  p.kind = ProfilePiece::Kind::Arc;
  p.centre = centre;
  p.radius = radius;
  p.angle_from = angle_from;
  p.angle_to = angle_to;
  p.mesh_steps = steps;
  return p;
}

}  // namespace

Eigen::Vector2d piecePoint(const ProfilePiece& piece, double t) {
  if (piece.kind == ProfilePiece::Kind::Line) return piece.from + t * (piece.to - piece.from);
  const double a = piece.angle_from + t * (piece.angle_to - piece.angle_from);
  return piece.centre + piece.radius * Eigen::Vector2d(std::cos(a), std::sin(a));
}

Eigen::Vector2d pieceTangent(const ProfilePiece& piece, double t) {
  if (piece.kind == ProfilePiece::Kind::Line) return piece.to - piece.from;
  const double span = piece.angle_to - piece.angle_from;
  const double a = piece.angle_from + t * span;
  return piece.radius * span * Eigen::Vector2d(-std::sin(a), std::cos(a));
}

Profile roundedCylinder(double radius, double z0, double z1, double fillet) {
  if (!(radius > 0) || !(z1 > z0) || fillet < 0 || 2 * fillet > z1 - z0 || fillet > radius)
    throw std::invalid_argument("roundedCylinder: needs radius > 0, z1 > z0 and a fillet no larger than "
                                "the radius or half the length");
  if (fillet == 0)
    return {line({0, z0}, {radius, z0}), line({radius, z0}, {radius, z1}), line({radius, z1}, {0, z1})};
  const double inner = radius - fillet;
  return {line({0, z0}, {inner, z0}),
          arc({inner, z0 + fillet}, fillet, -kPi / 2, 0, kFilletStepsPerQuarter),
          line({radius, z0 + fillet}, {radius, z1 - fillet}),
          arc({inner, z1 - fillet}, fillet, 0, kPi / 2, kFilletStepsPerQuarter),
          line({inner, z1}, {0, z1})};
}

Profile capsule(double radius, double length) {
  if (!(radius > 0) || !(length > 0))
    throw std::invalid_argument("capsule: needs radius > 0 and length > 0");
  return {arc({0, 0}, radius, -kPi / 2, 0, kCapStepsPerQuarter),
          line({radius, 0}, {radius, length}),
          arc({0, length}, radius, 0, kPi / 2, kCapStepsPerQuarter)};
}

Eigen::Isometry3d axisFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("axisFrame: the axis has zero length");
  const Eigen::Vector3d z = axis.normalized();
  // Seed x with the world axis least aligned with z, then make it orthogonal.
  Eigen::Vector3d seed = Eigen::Vector3d::UnitX();
  if (std::abs(z.x()) > 0.9) seed = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = (seed - seed.dot(z) * z).normalized();
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
  frame.linear().col(0) = x;
  frame.linear().col(1) = z.cross(x);
  frame.linear().col(2) = z;
  frame.translation() = origin;
  return frame;
}

}  // namespace xmate::robotgen
