// SPDX-License-Identifier: Apache-2.0
// Timing and sampling of cartesian_trajectory.h. Why the arc needs its own translation limits is
// explained in docs/planning.md ("Timing a Cartesian path").
#include "planning/cartesian_trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace xmate::planning {
namespace {

constexpr double kUnlimited = std::numeric_limits<double>::infinity();

// Bounds on the rates of one scalar coordinate: |first| <= v, |second| <= a, |third| <= j.
struct RateLimits {
  double v, a, j;
};

// Limits on the path length s such that the TCP's acceleration and jerk vectors stay within
// A and J although a curve of curvature k adds a normal part. On a circle,
//   |p''|^2   = s''^2 + k^2 s'^4,
//   |p'''|^2  = (s''' - k^2 s'^3)^2 + 9 k^2 s'^2 s''^2,
// so it is enough that v <= sqrt(A / (2k)) (normal acceleration at most A/2), a^2 + k^2 v^4 <= A^2,
// and j + k^2 v^3 <= sqrt(J^2 - 9 k^2 v^2 a^2); the caps below keep j >= (sqrt(3)/2 - 1/4) J > 0.
RateLimits pathLengthLimits(const RateLimits& tcp, double curvature) {
  if (curvature == 0) return tcp;
  const double k = curvature;
  RateLimits s;
  s.v = std::min({tcp.v, std::sqrt(tcp.a / (2 * k)), std::cbrt(tcp.j / (4 * k * k))});
  s.a = std::min(std::sqrt(tcp.a * tcp.a - k * k * s.v * s.v * s.v * s.v), tcp.j / (6 * k * s.v));
  const double normal_jerk = 3 * k * s.v * s.a;
  s.j = std::min(tcp.j, std::sqrt(tcp.j * tcp.j - normal_jerk * normal_jerk) - k * k * s.v * s.v * s.v);
  return s;
}

// Tightens `u` so that a quantity that changes by `change` over the whole path (x = change * u)
// stays within `limits`. A quantity that does not change sets no limit.
void limitBy(RateLimits& u, double change, const RateLimits& limits) {
  const double c = std::abs(change);
  if (c == 0) return;
  u.v = std::min(u.v, limits.v / c);
  u.a = std::min(u.a, limits.a / c);
  u.j = std::min(u.j, limits.j / c);
}

CartesianSample atRest(const Eigen::Isometry3d& pose, double psi, bool finished) {
  CartesianSample sample;
  sample.pose = pose;
  sample.psi = psi;
  sample.linear_velocity.setZero();
  sample.linear_acceleration.setZero();
  sample.angular_velocity.setZero();
  sample.angular_acceleration.setZero();
  sample.psi_velocity = 0;
  sample.psi_acceleration = 0;
  sample.finished = finished;
  return sample;
}

}  // namespace

CartesianTrajectory timePath(const CartesianPath& path, double speed_ratio,
                             const model::CartesianLimits& limits) {
  if (!(std::isfinite(speed_ratio) && speed_ratio > 0 && speed_ratio <= 1)) {
    std::ostringstream msg;
    msg << "Cartesian move: speed_ratio = " << speed_ratio << " is outside (0, 1]; pass e.g. 0.2";
    throw std::invalid_argument(msg.str());
  }
  const double r = speed_ratio;
  const RateLimits translation{limits.v_trans * r, limits.a_trans * r, limits.j_trans * r};
  const RateLimits rotation{limits.v_rot * r, limits.a_rot * r, limits.j_rot * r};
  const RateLimits elbow{limits.v_elbow * r, limits.a_elbow * r, limits.j_elbow * r};
  const double curvature = path.shape == PathShape::kArc ? 1 / path.radius : 0;

  RateLimits u{kUnlimited, kUnlimited, kUnlimited};
  limitBy(u, path.length, pathLengthLimits(translation, curvature));
  limitBy(u, path.rotation_angle, rotation);
  limitBy(u, path.psi_delta, elbow);

  CartesianTrajectory trajectory{path, DoubleSProfile{}};
  const bool moves = std::isfinite(u.v);
  if (moves) trajectory.timing = planDoubleS(1.0, u.v, u.a, u.j);
  return trajectory;
}

CartesianTrajectory planLine(double speed_ratio, const PathPoint& start, const PathPoint& target) {
  return timePath(makeLinePath(start, target), speed_ratio);
}

CartesianTrajectory planArc(double speed_ratio, const PathPoint& start, const PathPoint& via,
                            const PathPoint& target) {
  return timePath(makeArcPath(start, via, target), speed_ratio);
}

double duration(const CartesianTrajectory& trajectory) { return trajectory.timing.duration; }

CartesianSample sampleTrajectory(const CartesianTrajectory& trajectory, double t) {
  if (std::isnan(t))
    throw std::invalid_argument("Cartesian move: time t is NaN; pass the time since the move began, in s");
  const CartesianPath& path = trajectory.path;
  if (t >= trajectory.timing.duration) return atRest(path.target.pose, path.target.psi, true);
  if (t <= 0) return atRest(path.start.pose, path.start.psi, false);

  const DoubleSSample u = sampleDoubleS(trajectory.timing, t);
  const PathState at = evaluatePath(path, u.p);
  CartesianSample sample;
  sample.pose.linear() = at.rotation;
  sample.pose.translation() = at.position;
  sample.pose.makeAffine();
  sample.psi = at.psi;
  // Chain rule: dp/dt = p' u',  d2p/dt2 = p'' u'^2 + p' u''  (primes on the path: d/du).
  sample.linear_velocity = at.dposition_du * u.v;
  sample.linear_acceleration = at.d2position_du2 * (u.v * u.v) + at.dposition_du * u.a;
  // The rotation axis is fixed, so the angular rates are plain multiples of u' and u''.
  sample.angular_velocity = at.omega_du * u.v;
  sample.angular_acceleration = at.omega_du * u.a;
  sample.psi_velocity = path.psi_delta * u.v;
  sample.psi_acceleration = path.psi_delta * u.a;
  sample.finished = false;
  return sample;
}

std::array<double, 6> velocityOf(const CartesianSample& sample) {
  const Eigen::Vector3d& v = sample.linear_velocity;
  const Eigen::Vector3d& w = sample.angular_velocity;
  return {v.x(), v.y(), v.z(), w.x(), w.y(), w.z()};
}

std::array<double, 6> accelerationOf(const CartesianSample& sample) {
  const Eigen::Vector3d& a = sample.linear_acceleration;
  const Eigen::Vector3d& w = sample.angular_acceleration;
  return {a.x(), a.y(), a.z(), w.x(), w.y(), w.z()};
}

}  // namespace xmate::planning
