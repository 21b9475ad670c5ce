// SPDX-License-Identifier: Apache-2.0
// Line and arc geometry of cartesian_path.h (docs/planning.md, "Cartesian paths").
#include "planning/cartesian_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include <xmate/exception.h>

#include "planning/cartesian_pose.h"

namespace xmate::planning {
namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;
constexpr double kMinPointDistance = 1e-4;  // m: closer points are "coincident"
constexpr double kMaxArcRadius = 100.0;     // m: a larger circle is a line in practice
constexpr double kMinTriangleSine = 1e-6;   // smaller sine of any triangle angle: collinear

void requirePathPoint(const PathPoint& point, const char* what) {
  requireRigidTransform(point.pose.matrix(), what);
  if (!std::isfinite(point.psi)) {
    std::ostringstream msg;
    msg << what << ": arm angle psi = " << point.psi << " is not finite; pass the arm angle in rad";
    throw std::invalid_argument(msg.str());
  }
}

// Shortest rotation from the start to the target orientation, in the start's tool frame.
void setOrientationChange(CartesianPath& path) {
  const Eigen::Matrix3d relative = path.start.pose.linear().transpose() * path.target.pose.linear();
  const Eigen::AngleAxisd rotation(Eigen::Quaterniond(relative).normalized());  // angle in [0, pi]
  path.rotation_angle = rotation.angle();
  path.rotation_axis = rotation.angle() > 0 ? rotation.axis() : Eigen::Vector3d::UnitZ();
}

CartesianPath pathBetween(PathShape shape, const PathPoint& start, const PathPoint& target) {
  CartesianPath path;
  path.shape = shape;
  path.start = start;
  path.target = target;
  setOrientationChange(path);
  path.psi_delta = target.psi - start.psi;
  return path;
}

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f mm", metres * 1000);
  return text;
}

void rejectCoincident(const Eigen::Vector3d& a, const char* a_name, const Eigen::Vector3d& b,
                      const char* b_name) {
  const double distance = (a - b).norm();
  if (distance >= kMinPointDistance) return;
  throw MotionException(std::string("MOVEC: the ") + a_name + " and " + b_name + " positions are " +
                        millimetres(distance) + " apart (less than " + millimetres(kMinPointDistance) +
                        "), so they do not define a circle; move them apart or use MOVEL");
}

// The sine of the triangle's angle at `corner` between the sides to `a` and `b`.
double sineAt(const Eigen::Vector3d& corner, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - corner, v = b - corner;
  return u.cross(v).norm() / (u.norm() * v.norm());
}

void rejectCollinear(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  const double twice_area = (p1 - p0).cross(p2 - p0).norm();
  const double sides = (p1 - p0).norm() * (p2 - p1).norm() * (p2 - p0).norm();
  const double circumradius = sides / (2 * twice_area);  // infinite when exactly collinear
  const double smallest_sine = std::min({sineAt(p0, p1, p2), sineAt(p1, p0, p2), sineAt(p2, p0, p1)});
  if (circumradius <= kMaxArcRadius && smallest_sine >= kMinTriangleSine) return;
  const double via_offset = twice_area / (p2 - p0).norm();  // distance of via from the start-target line
  throw MotionException("MOVEC: start, via and target are collinear (via is " + millimetres(via_offset) +
                        " off the line through start and target); move the via point off the line "
                        "or use MOVEL");
}

// Angle of point p on the arc's circle, measured from e1 towards e2, in [0, 2 pi).
double arcAngleOf(const CartesianPath& path, const Eigen::Vector3d& p) {
  const Eigen::Vector3d r = p - path.centre;
  const double angle = std::atan2(r.dot(path.e2), r.dot(path.e1));
  return angle < 0 ? angle + kTwoPi : angle;
}

}  // namespace

CartesianPath makeLinePath(const PathPoint& start, const PathPoint& target) {
  requirePathPoint(start, "MOVEL start pose");
  requirePathPoint(target, "MOVEL target pose");
  CartesianPath path = pathBetween(PathShape::kLine, start, target);
  path.length = (target.pose.translation() - start.pose.translation()).norm();
  return path;
}

CartesianPath makeArcPath(const PathPoint& start, const PathPoint& via, const PathPoint& target) {
  requirePathPoint(start, "MOVEC start pose");
  requirePathPoint(via, "MOVEC via pose");
  requirePathPoint(target, "MOVEC target pose");
  const Eigen::Vector3d p0 = start.pose.translation();
  const Eigen::Vector3d p1 = via.pose.translation();
  const Eigen::Vector3d p2 = target.pose.translation();
  rejectCoincident(p0, "start", p1, "via");
  rejectCoincident(p1, "via", p2, "target");
  rejectCoincident(p0, "start", p2, "target");
  rejectCollinear(p0, p1, p2);

  CartesianPath path = pathBetween(PathShape::kArc, start, target);
  // Circumcentre of the triangle: p0 + ((|a|^2 b - |b|^2 a) x (a x b)) / (2 |a x b|^2).
  const Eigen::Vector3d a = p1 - p0, b = p2 - p0, normal = a.cross(b);
  path.centre = p0 + (a.squaredNorm() * b - b.squaredNorm() * a).cross(normal) / (2 * normal.squaredNorm());
  path.radius = (p0 - path.centre).norm();
  // The triangle p0, p1, p2 turns positively about `normal`, and so do the points around the circle:
  // measured about it from p0, the via point comes before the target.
  path.e1 = (p0 - path.centre) / path.radius;
  path.e2 = normal.normalized().cross(path.e1);
  path.sweep = arcAngleOf(path, p2);
  path.via_u = arcAngleOf(path, p1) / path.sweep;
  path.length = path.radius * path.sweep;
  return path;
}

PathState evaluatePath(const CartesianPath& path, double u) {
  const double w = std::clamp(u, 0.0, 1.0);
  const Eigen::Vector3d p0 = path.start.pose.translation();
  PathState state;
  if (path.shape == PathShape::kLine) {
    const Eigen::Vector3d chord = path.target.pose.translation() - p0;
    state.position = p0 + w * chord;
    state.dposition_du = chord;
    state.d2position_du2.setZero();
  } else {
    const double angle = path.sweep * w, c = std::cos(angle), s = std::sin(angle);
    const Eigen::Vector3d radial = c * path.e1 + s * path.e2;    // centre -> point
    const Eigen::Vector3d tangent = -s * path.e1 + c * path.e2;  // direction of travel
    state.position = path.centre + path.radius * radial;
    state.dposition_du = path.radius * path.sweep * tangent;
    state.d2position_du2 = -path.radius * path.sweep * path.sweep * radial;
  }
  const Eigen::Matrix3d r0 = path.start.pose.linear();
  state.rotation = r0 * Eigen::AngleAxisd(path.rotation_angle * w, path.rotation_axis).toRotationMatrix();
  state.omega_du = path.rotation_angle * (r0 * path.rotation_axis);
  state.psi = path.start.psi + path.psi_delta * w;

  // The end points exactly as given, not as recomputed.
  const PathPoint* end = u <= 0 ? &path.start : (u >= 1 ? &path.target : nullptr);
  if (end != nullptr) {
    state.position = end->pose.translation();
    state.rotation = end->pose.linear();
    state.psi = end->psi;
  }
  return state;
}

PathPoint pathPoint(const std::array<double, 16>& row_major_pose, double psi, const char* what) {
  return {poseFromRowMajor(row_major_pose, what), psi};
}

}  // namespace xmate::planning
