// SPDX-License-Identifier: Apache-2.0
// LimitWatch (limit_check.h): the joint range, the soft limits and the safety box along a motion.
#include "client/limit_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace xmate::client {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
// Rounding: a joint or the TCP exactly on a limit is inside.
constexpr double kJointSlack = 1e-9;  // rad
constexpr double kBoxSlack = 1e-9;    // m
// Samples of a joint line for the box check (joints move monotonically: their ends suffice).
constexpr int kLineSamples = 200;

Eigen::Isometry3d isometry(const std::array<double, 16>& m) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose.linear()(r, c) = m[size_t(4 * r + c)];
    pose.translation()[r] = m[size_t(4 * r + 3)];
  }
  return pose;
}

std::string fmt(const char* format, double a, double b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

}  // namespace

LimitWatch::LimitWatch(const model::RobotSpec& spec, const MotionLimits& limits, const std::array<double, 7>& q_start,
                       const model::ArmKinematics* model)
    : spec_(spec), model_(model), limits_(limits) {
  if (!model_) limits_.box_active = false;
  for (int i = 0; i < spec_.dof; ++i) {
    lower_[i] = std::min(spec_.q_min[i], q_start[i]);
    upper_[i] = std::max(spec_.q_max[i], q_start[i]);
    soft_lower_[i] = std::min(limits_.soft_lower[i], q_start[i]);
    soft_upper_[i] = std::max(limits_.soft_upper[i], q_start[i]);
  }
  if (!limits_.box_active) return;
  box_to_base_ = isometry(limits_.box_frame);
  const Eigen::Vector3d half = 0.5 * Eigen::Vector3d(limits_.box_size[0], limits_.box_size[1], limits_.box_size[2]);
  const Eigen::Vector3d local = box_to_base_.inverse() * isometry(model_->GetCartPose(q_start)).translation();
  box_lower_ = (-half).cwiseMin(local);
  box_upper_ = half.cwiseMax(local);
}

std::string LimitWatch::checkJoints(const std::array<double, 7>& q) const {
  for (int i = 0; i < spec_.dof; ++i) {
    const int n = i + 1;
    if (q[i] > upper_[i] + kJointSlack)
      return "joint " + std::to_string(n) + fmt(" would reach %.2f deg, beyond its upper limit of %.2f deg", q[i] * kDeg,
                                                spec_.q_max[i] * kDeg);
    if (q[i] < lower_[i] - kJointSlack)
      return "joint " + std::to_string(n) + fmt(" would reach %.2f deg, beyond its lower limit of %.2f deg", q[i] * kDeg,
                                                spec_.q_min[i] * kDeg);
    if (!limits_.has_soft_limits) continue;
    if (q[i] > soft_upper_[i] + kJointSlack)
      return "joint " + std::to_string(n) +
             fmt(" would reach %.2f deg, beyond its soft upper limit of %.2f deg (setJointLimit)", q[i] * kDeg,
                 limits_.soft_upper[i] * kDeg);
    if (q[i] < soft_lower_[i] - kJointSlack)
      return "joint " + std::to_string(n) +
             fmt(" would reach %.2f deg, beyond its soft lower limit of %.2f deg (setJointLimit)", q[i] * kDeg,
                 limits_.soft_lower[i] * kDeg);
  }
  return "";
}

std::string LimitWatch::checkBox(const Eigen::Vector3d& local) const {
  static const char* const kAxis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    const double half = 0.5 * limits_.box_size[size_t(a)];
    if (local[a] > box_upper_[a] + kBoxSlack)
      return std::string("the TCP would leave the safety box through its +") + kAxis[a] +
             fmt(" face (%.3f m from the box centre) and reach %.3f m (setCartesianLimit)", half, local[a]);
    if (local[a] < box_lower_[a] - kBoxSlack)
      return std::string("the TCP would leave the safety box through its -") + kAxis[a] +
             fmt(" face (%.3f m from the box centre) and reach %.3f m (setCartesianLimit)", -half, local[a]);
  }
  return "";
}

// As the controller does: an allowance beyond a limit narrows to where the joint or TCP came back to.
void LimitWatch::narrow(const std::array<double, 7>& q, const Eigen::Vector3d& local) {
  for (int i = 0; i < spec_.dof; ++i) {
    upper_[i] = std::max(spec_.q_max[i], std::min(upper_[i], q[i]));
    lower_[i] = std::min(spec_.q_min[i], std::max(lower_[i], q[i]));
    soft_upper_[i] = std::max(limits_.soft_upper[i], std::min(soft_upper_[i], q[i]));
    soft_lower_[i] = std::min(limits_.soft_lower[i], std::max(soft_lower_[i], q[i]));
  }
  if (!limits_.box_active) return;
  const Eigen::Vector3d half = 0.5 * Eigen::Vector3d(limits_.box_size[0], limits_.box_size[1], limits_.box_size[2]);
  box_upper_ = half.cwiseMax(box_upper_.cwiseMin(local));
  box_lower_ = (-half).cwiseMin(box_lower_.cwiseMax(local));
}

std::string LimitWatch::check(const std::array<double, 7>& q, const std::string& where) {
  std::string problem = checkJoints(q);
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  if (problem.empty() && limits_.box_active) {
    local = box_to_base_.inverse() * isometry(model_->GetCartPose(q)).translation();
    problem = checkBox(local);
  }
  if (!problem.empty()) return problem + " " + where;
  narrow(q, local);
  return "";
}

std::string checkJointLine(LimitWatch& watch, const std::array<double, 7>& q_start,
                           const std::array<double, 7>& q_target, int dof) {
  std::vector<std::array<double, 7>> samples(kLineSamples, q_start);
  for (int k = 1; k <= kLineSamples; ++k)
    for (int i = 0; i < dof; ++i)
      samples[size_t(k - 1)][i] = q_start[i] + double(k) / kLineSamples * (q_target[i] - q_start[i]);
  return checkJointPath(watch, samples);
}

std::string checkJointPath(LimitWatch& watch, const std::vector<std::array<double, 7>>& samples) {
  if (samples.empty()) return "";
  // The target first (as the path reaches it), so that a target beyond a limit is named as such.
  LimitWatch at_target = watch;
  if (std::string problem = at_target.check(samples.back(), "at the target"); !problem.empty()) return problem;
  for (size_t k = 0; k < samples.size(); ++k) {
    char where[48];
    std::snprintf(where, sizeof where, "%.0f %% of the way", 100.0 * double(k + 1) / double(samples.size()));
    const bool last = k + 1 == samples.size();
    const std::string problem = watch.check(samples[k], last ? std::string("at the target") : std::string(where));
    if (!problem.empty()) return problem;
  }
  return "";
}

}  // namespace xmate::client
