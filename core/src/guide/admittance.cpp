// SPDX-License-Identifier: Apache-2.0
// guide::AdmittanceGuide (admittance.h): the sensor's wrench, less bias and tool weight, through a
// dead band into a virtual mass-damper at the flange; its velocity mapped to the joints by the
// damped least-squares inverse of the Jacobian, held within axis speeds, ranges and bounds.
#include "guide/admittance.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "net/clock.h"

namespace xmate::guide {
namespace {

constexpr double kGravity = 9.80665;          // m/s^2, along -z of the base
constexpr double kDampingLambda = 0.01;       // damped least squares near singular poses
constexpr double kFollowTolerance = 0.1;      // the flange may move 10 % off the pushed direction
constexpr double kRestLinear = 1e-4;          // m/s: "at rest"
constexpr double kRestAngular = 1e-3;         // rad/s
constexpr double kRangeMargin = 0.5 * 3.14159265358979323846 / 180.0;  // keep half a degree off the hard ranges

Eigen::Matrix3d rotationOf(const std::array<double, 16>& pose) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = pose[size_t(4 * i + j)];
  return r;
}

// Shrinks `v` (3 values from `at`) by `by` towards zero, never past it.
void brake(std::array<double, 6>& v, size_t at, double by) {
  const double n = std::sqrt(v[at] * v[at] + v[at + 1] * v[at + 1] + v[at + 2] * v[at + 2]);
  const double scale = n > by ? (n - by) / n : 0.0;
  for (size_t i = at; i < at + 3; ++i) v[i] *= scale;
}

// Caps the length of 3 values from `at` at `max`.
void cap(std::array<double, 6>& v, size_t at, double max) {
  const double n = std::sqrt(v[at] * v[at] + v[at + 1] * v[at + 1] + v[at + 2] * v[at + 2]);
  if (n > max)
    for (size_t i = at; i < at + 3; ++i) v[i] *= max / n;
}

// The part of a vector beyond a dead band: zero below it, its length less the band above.
Eigen::Vector3d beyondDeadBand(const Eigen::Vector3d& v, double band) {
  const double n = v.norm();
  return n > band ? Eigen::Vector3d(v * ((n - band) / n)) : Eigen::Vector3d::Zero();
}

}  // namespace

std::array<double, 6> toolWeightAtSensor(const ToolWeight& tool, const std::array<double, 16>& flange_in_base) {
  const Eigen::Vector3d force = rotationOf(flange_in_base).transpose() * Eigen::Vector3d(0, 0, -tool.mass * kGravity);
  const Eigen::Vector3d torque = Eigen::Vector3d(tool.center[0], tool.center[1], tool.center[2]).cross(force);
  return {force.x(), force.y(), force.z(), torque.x(), torque.y(), torque.z()};
}

const char* describe(GuideEnd end) {
  switch (end) {
    case GuideEnd::kRunning: return "guiding";
    case GuideEnd::kOperator: return "stopped by the operator";
    case GuideEnd::kSensorSilent:
      return "the force sensor fell silent: check its cable and power, then start guiding again";
  }
  return "?";
}

AdmittanceGuide::AdmittanceGuide(const model::ArmKinematics& model, const WrenchSource& sensor, double cycle_s,
                                 GuideParameters parameters, ToolWeight tool)
    : model_(model), sensor_(sensor), parameters_(parameters), tool_(tool), dt_(cycle_s) {
  model_.SetCoor({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, "AdmittanceGuide");
  const model::RobotSpec& spec = model.spec();
  for (size_t i = 0; i < 7; ++i) {
    lower_[i] = spec.q_min[i] + kRangeMargin;
    upper_[i] = spec.q_max[i] - kRangeMargin;
  }
}

void AdmittanceGuide::setJointBounds(const std::array<double, 7>& lower, const std::array<double, 7>& upper) {
  for (size_t i = 0; i < 7; ++i) {
    lower_[i] = std::max(lower_[i], lower[i]);
    upper_[i] = std::min(upper_[i], upper[i]);
  }
}

GuideStatus AdmittanceGuide::status() const {
  GuideStatus s;
  status_.load(s);
  return s;
}

void AdmittanceGuide::stepVelocity(const std::array<double, 6>& wrench_base, double dt, bool stopping) {
  if (stopping) {
    brake(velocity_, 0, parameters_.braking * dt);
    brake(velocity_, 3, parameters_.braking * dt);
    return;
  }
  for (size_t i = 0; i < 3; ++i) {
    velocity_[i] += dt * (wrench_base[i] - parameters_.damping * velocity_[i]) / parameters_.mass;
    velocity_[i + 3] +=
        dt * (wrench_base[i + 3] - parameters_.rotational_damping * velocity_[i + 3]) / parameters_.inertia;
  }
  cap(velocity_, 0, parameters_.max_speed);
  cap(velocity_, 3, parameters_.max_angular_speed);
}

bool AdmittanceGuide::command(const arm::ArmSample& now, std::array<double, 7>& q) {
  std::array<double, 6> raw{};
  int64_t received_ns = 0;
  const bool have = sensor_.read(raw, received_ns);
  const bool fresh = have && net::monotonicNs() - received_ns <= int64_t(parameters_.sensor_timeout_s * 1e9);
  if (!started_) {
    started_ = true;
    q_ = now.q_command;
    const std::array<double, 6> weight = toolWeightAtSensor(tool_, model_.GetCartPose(q_));
    for (size_t i = 0; i < 6; ++i) bias_[i] = raw[i] - weight[i];
  }
  if (ending_ == GuideEnd::kRunning && !fresh) ending_ = GuideEnd::kSensorSilent;
  if (ending_ == GuideEnd::kRunning && stop_.load(std::memory_order_acquire)) ending_ = GuideEnd::kOperator;
  const bool stopping = ending_ != GuideEnd::kRunning;

  // The wrench the operator applies, in the base frame.
  const std::array<double, 16> flange = model_.GetCartPose(q_);
  const Eigen::Matrix3d r = rotationOf(flange);
  std::array<double, 6> wrench{};
  if (!stopping) {
    const std::array<double, 6> weight = toolWeightAtSensor(tool_, flange);
    Eigen::Vector3d force, torque;
    for (int i = 0; i < 3; ++i) {
      force[i] = raw[size_t(i)] - bias_[size_t(i)] - weight[size_t(i)];
      torque[i] = raw[size_t(i) + 3] - bias_[size_t(i) + 3] - weight[size_t(i) + 3];
    }
    force = beyondDeadBand(r * force, parameters_.force_dead_band);
    torque = beyondDeadBand(r * torque, parameters_.torque_dead_band);
    if (parameters_.axes == GuideAxes::kRotation) force.setZero();
    if (parameters_.axes == GuideAxes::kTranslation) torque.setZero();
    wrench = {force.x(), force.y(), force.z(), torque.x(), torque.y(), torque.z()};
  }
  stepVelocity(wrench, dt_, stopping);

  // The joints that follow the flange: damped least squares, then within the axis speeds.
  const std::array<double, 42> jacobian = model_.Jacobian(q_);
  const Eigen::Map<const Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> j(jacobian.data());
  const Eigen::Map<const Eigen::Matrix<double, 6, 1>> v(velocity_.data());
  const Eigen::Matrix<double, 6, 6> jjt =
      j * j.transpose() + kDampingLambda * kDampingLambda * Eigen::Matrix<double, 6, 6>::Identity();
  Eigen::Matrix<double, 7, 1> dq = j.transpose() * jjt.ldlt().solve(v);
  // Near the edge of the reach or a singular pose the damped inverse moves the flange elsewhere than
  // it is pushed: hold still there rather than drift -- unless the step leads away from that pose
  // (the arm's manipulability grows), so the operator can always pull it back.
  const Eigen::Matrix<double, 6, 1> miss = j * dq - v;
  const bool off_course = miss.head<3>().norm() > kFollowTolerance * v.head<3>().norm() + 1e-4 ||
                          miss.tail<3>().norm() > kFollowTolerance * v.tail<3>().norm() + 1e-3;
  now_.cannot_follow = false;
  if (off_course) {
    std::array<double, 7> ahead = q_;
    for (int i = 0; i < 7; ++i) ahead[size_t(i)] += dq[i] * dt_;
    const std::array<double, 42> jacobian_ahead = model_.Jacobian(ahead);
    const Eigen::Map<const Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> j_ahead(jacobian_ahead.data());
    now_.cannot_follow = (j_ahead * j_ahead.transpose()).determinant() <= (j * j.transpose()).determinant();
  }
  if (now_.cannot_follow) {
    dq.setZero();
    velocity_ = {};
  }
  const model::RobotSpec& spec = model_.spec();
  double scale = 1;
  for (int i = 0; i < spec.dof; ++i) {
    const double allowed = spec.dq_max[size_t(i)] * parameters_.axis_speed_share;
    if (std::abs(dq[i]) * scale > allowed) scale = allowed / std::abs(dq[i]);
  }
  dq *= scale;
  for (double& component : velocity_) component *= scale;  // the virtual motion goes as fast as the arm

  now_.limited_axis = -1;
  for (int i = 0; i < spec.dof; ++i) {
    const double next = q_[size_t(i)] + dq[i] * dt_;
    // Within the bounds; an axis that starts beyond one may only move back inside.
    const double lo = std::min(lower_[size_t(i)], q_[size_t(i)]);
    const double hi = std::max(upper_[size_t(i)], q_[size_t(i)]);
    const double held = std::clamp(next, lo, hi);
    if (held != next) now_.limited_axis = i;
    q_[size_t(i)] = held;
  }
  if (now_.limited_axis >= 0) {  // the operator pushes into a wall: the virtual motion stops there
    for (double& component : velocity_) component = 0;
  }
  q = q_;

  ++now_.cycles;
  now_.wrench = wrench;
  now_.velocity = velocity_;
  const double linear = std::hypot(velocity_[0], velocity_[1], velocity_[2]);
  const double angular = std::hypot(velocity_[3], velocity_[4], velocity_[5]);
  const bool done = stopping && linear < kRestLinear && angular < kRestAngular;
  now_.end = ending_;
  status_.store(now_);
  return done;
}

}  // namespace xmate::guide
