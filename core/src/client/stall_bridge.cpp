// SPDX-License-Identifier: Apache-2.0
// StallBridge (stall_bridge.h): the controller's extrapolation over a gap in the commands, and the
// third-order tracker that brings the command back onto the plan.
#include "client/stall_bridge.h"

#include <algorithm>
#include <cmath>

namespace xmate::client {
namespace {

constexpr double kDt = 1e-3;  // s per message_id
// The tracker's three poles at -kPole (1/s): the correction is mostly gone after ~8 / kPole = 0.2 s.
constexpr double kPole = 40.0;
// Below these the correction is over (the final step of at most 1e-9 is far below any tolerance).
// The share of the rated jerk plan and correction use together: the rest absorbs rounding and the
// sampling of the plan's own jerk.
constexpr double kJerkUse = 0.95;
constexpr double kDoneE = 1e-9, kDoneDe = 1e-7, kDoneDde = 1e-5;

}  // namespace

StallBridge::StallBridge(int dims, const Limits& limits) : dims_(std::clamp(dims, 1, kMaxDims)), limits_(limits) {}

void StallBridge::startAt(uint64_t message_id, const Vec& commanded) {
  sent_.fill(commanded);
  for (int k = 0; k < 3; ++k) sent_id_[size_t(k)] = message_id - 1 - uint64_t(k);
  sent_count_ = 3;
  seeded_ = true;
}

bool StallBridge::needsPlanHistory(uint64_t message_id) const {
  return active_ || seeded_ || (sent_count_ >= 3 && message_id > sent_id_[0] + 1);
}

StallBridge::Vec StallBridge::bridge(uint64_t message_id, const PlanWindow& plan) {
  const bool gap = sent_count_ >= 3 && message_id > sent_id_[0] + 1;
  if (gap || seeded_) {
    startFromExtrapolation(message_id, plan);
    if (!seeded_) ++stalls_;
    seeded_ = false;
  } else {
    step(planRates(plan));
    settleIfDone();
  }
  Vec out = plan.now;
  for (int i = 0; i < dims_; ++i) out[i] += e_[i];
  return out;
}

StallBridge::PlanRates StallBridge::planRates(const PlanWindow& plan) const {
  PlanRates r;
  for (int i = 0; i < dims_; ++i) {
    const double a_now = (plan.now[i] - 2 * plan.before_1[i] + plan.before_2[i]) / (kDt * kDt);
    r.acceleration[i] = (plan.next[i] - 2 * plan.now[i] + plan.before_1[i]) / (kDt * kDt);
    r.velocity[i] = (plan.now[i] - plan.before_1[i]) / kDt + 0.5 * kDt * a_now;
    r.jerk[i] = (r.acceleration[i] - a_now) / kDt;
  }
  return r;
}

// The controller's rule for lost commands: the last command that arrived, continued with the
// velocity and acceleration of the last three (divided differences over their message_ids). The
// correction starts as the difference between that and the plan, in position, velocity and
// acceleration, so the first command after the gap continues what the controller did meanwhile.
void StallBridge::startFromExtrapolation(uint64_t message_id, const PlanWindow& plan_window) {
  const Vec& plan = plan_window.now;
  const Vec& plan_1 = plan_window.before_1;
  const Vec& plan_2 = plan_window.before_2;
  const double t0 = double(sent_id_[0]) * kDt, t1 = double(sent_id_[1]) * kDt, t2 = double(sent_id_[2]) * kDt;
  const double tau = double(message_id) * kDt - t0;
  for (int i = 0; i < dims_; ++i) {
    const double v1 = (sent_[0][i] - sent_[1][i]) / (t0 - t1);
    const double v2 = (sent_[1][i] - sent_[2][i]) / (t1 - t2);
    const double a = 2 * (v1 - v2) / (t0 - t2);
    const double v = v1 + 0.5 * (t0 - t1) * a;  // the divided difference belongs half an interval back
    const double x_e = sent_[0][i] + v * tau + 0.5 * a * tau * tau;
    const double a_plan = (plan[i] - 2 * plan_1[i] + plan_2[i]) / (kDt * kDt);
    const double v_plan = (plan[i] - plan_1[i]) / kDt + 0.5 * kDt * a_plan;
    e_[i] = x_e - plan[i];
    de_[i] = v + a * tau - v_plan;
    dde_[i] = a - a_plan;
  }
  active_ = true;
}

// Scales each group of v down to the norm limit[group] (coordinates of a group share one factor).
void StallBridge::limitGroups(Vec& v, const Vec& limit) const {
  for (int g = 0; g < dims_; ++g) {
    const double norm = groupNorm(v, g);
    if (norm <= limit[g]) continue;
    const double scale = limit[g] / norm;
    for (int i = 0; i < dims_; ++i)
      if (limits_.group[i] == g) v[i] *= scale;
  }
}

// The velocity guard: where a group's total velocity (plan + correction) and its correction's
// acceleration point the same way, that acceleration is held to sqrt(2 j (v_max - |v|)) -- what the
// jerk reserve j can still take back before the velocity reaches v_max -- by lowering the
// correction's jerk (the jerk reserve still bounds it).
void StallBridge::guardVelocity(const Vec& velocity, Vec& jerk) const {
  for (int g = 0; g < dims_; ++g) {
    if (limits_.velocity[g] <= 0) continue;
    double along = 0;
    const double speed = groupNorm(velocity, g);
    if (speed <= 0) continue;
    for (int i = 0; i < dims_; ++i)
      if (limits_.group[i] == g) along += (dde_[i] + jerk[i] * kDt) * velocity[i] / speed;
    const double room = std::max(0.0, limits_.velocity[g] - speed);
    const double allowed = std::sqrt(2.0 * limits_.jerk_reserve[g] * room);
    if (along <= allowed) continue;
    for (int i = 0; i < dims_; ++i)
      if (limits_.group[i] == g) jerk[i] -= (along - allowed) / kDt * velocity[i] / speed;
  }
}

// The norm of a group's coordinates of v (the group starting at coordinate g).
double StallBridge::groupNorm(const Vec& v, int g) const {
  double norm2 = 0;
  for (int i = 0; i < dims_; ++i)
    if (limits_.group[i] == g) norm2 += v[i] * v[i];
  return std::sqrt(norm2);
}

// One cycle of the tracker: jerk = -(3p e'' + 3p^2 e' + p^3 e), guarded against the velocity
// limit, within what the plan leaves of the rated jerk (at least the reserve); then the command's
// acceleration within the limit. The acceleration limited is the one the controller will measure
// with the next command -- the plan's second difference centred on this cycle plus the correction's
// acceleration at its end -- less what the correction's jerk can add to a second difference
// (jerk dt / 3). The correction is integrated exactly for the jerk held over the cycle (a cubic
// piece), so its divided differences are those of a smooth curve, also right after the extrapolated
// start.
void StallBridge::step(const PlanRates& plan) {
  Vec jerk{}, velocity{}, available{}, allowed{};
  for (int i = 0; i < dims_; ++i) {
    jerk[i] = -(3 * kPole * dde_[i] + 3 * kPole * kPole * de_[i] + kPole * kPole * kPole * e_[i]);
    velocity[i] = plan.velocity[i] + de_[i];
  }
  for (int g = 0; g < dims_; ++g) {
    if (limits_.group[g] != g) continue;
    available[g] = std::max(limits_.jerk_reserve[g], kJerkUse * limits_.jerk[g] - groupNorm(plan.jerk, g));
    allowed[g] = std::max(0.0, limits_.acceleration[g] - available[g] * kDt / 3);
  }
  guardVelocity(velocity, jerk);
  limitGroups(jerk, available);
  Vec total{};
  for (int i = 0; i < dims_; ++i) total[i] = dde_[i] + jerk[i] * kDt + plan.acceleration[i];
  limitGroups(total, allowed);
  Vec held_jerk{};
  for (int i = 0; i < dims_; ++i) held_jerk[i] = (total[i] - plan.acceleration[i] - dde_[i]) / kDt;
  limitGroups(held_jerk, available);  // smooth first: an acceleration the jerk cannot reach waits a cycle
  for (int i = 0; i < dims_; ++i) {
    e_[i] += de_[i] * kDt + dde_[i] * kDt * kDt / 2 + held_jerk[i] * kDt * kDt * kDt / 6;
    de_[i] += dde_[i] * kDt + held_jerk[i] * kDt * kDt / 2;
    dde_[i] += held_jerk[i] * kDt;
  }
}

void StallBridge::settleIfDone() {
  for (int i = 0; i < dims_; ++i)
    if (std::abs(e_[i]) > kDoneE || std::abs(de_[i]) > kDoneDe || std::abs(dde_[i]) > kDoneDde) return;
  active_ = false;
  e_ = de_ = dde_ = Vec{};
}

StallBridge::Vec StallBridge::remember(uint64_t message_id, const Vec& command) {
  sent_[2] = sent_[1];
  sent_[1] = sent_[0];
  sent_[0] = command;
  sent_id_[2] = sent_id_[1];
  sent_id_[1] = sent_id_[0];
  sent_id_[0] = message_id;
  sent_count_ = std::min(sent_count_ + 1, 3);
  return command;
}

StallBridge::Limits jointBridgeLimits(const model::RobotSpec& spec, double share) {
  const double reserve = std::max(1.0 - share, 0.1);
  StallBridge::Limits limits;
  for (int i = 0; i < spec.dof; ++i) {
    limits.velocity[i] = spec.dq_max[i];
    limits.acceleration[i] = spec.ddq_max[i];
    limits.jerk[i] = spec.jerk_max[i];
    limits.jerk_reserve[i] = reserve * spec.jerk_max[i];
  }
  return limits;
}

StallBridge::Limits cartesianBridgeLimits(double share) {
  const double reserve = std::max(1.0 - share, 0.1);
  const model::CartesianLimits& controller = model::controllerCartesianLimits();
  const model::CartesianLimits& planner = model::plannerCartesianLimits();
  StallBridge::Limits limits;
  for (int i = 0; i < 3; ++i) {
    limits.velocity[i] = controller.v_trans;
    limits.velocity[i + 3] = controller.v_rot;
    limits.acceleration[i] = controller.a_trans;
    limits.jerk[i] = controller.j_trans;
    limits.jerk[i + 3] = controller.j_rot;
    limits.jerk_reserve[i] = reserve * planner.j_trans;
    limits.acceleration[i + 3] = controller.a_rot;
    limits.jerk_reserve[i + 3] = reserve * planner.j_rot;
  }
  limits.velocity[6] = controller.v_elbow;
  limits.acceleration[6] = controller.a_elbow;
  limits.jerk[6] = controller.j_elbow;
  limits.jerk_reserve[6] = reserve * planner.j_elbow;
  limits.group = {0, 0, 0, 3, 3, 3, 6};
  return limits;
}

StallBridge::Vec cartesianCoordinates(const Eigen::Isometry3d& pose, double psi, const Eigen::Matrix3d& reference) {
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(pose.linear() * reference.transpose()));
  const Eigen::Vector3d rotation = turn.angle() * turn.axis();
  const Eigen::Vector3d& p = pose.translation();
  return {p.x(), p.y(), p.z(), rotation.x(), rotation.y(), rotation.z(), psi};
}

StallBridge::Vec cartesianCoordinates(const std::array<double, 16>& m, double psi, const Eigen::Matrix3d& reference) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose.linear()(r, c) = m[size_t(4 * r + c)];
    pose.translation()[r] = m[size_t(4 * r + 3)];
  }
  return cartesianCoordinates(pose, psi, reference);
}

Eigen::Isometry3d poseFromCoordinates(const StallBridge::Vec& c, const Eigen::Matrix3d& reference) {
  const Eigen::Vector3d rotation(c[3], c[4], c[5]);
  const double angle = rotation.norm();
  const Eigen::Matrix3d turn =
      angle > 0 ? Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = turn * reference;
  pose.translation() = Eigen::Vector3d(c[0], c[1], c[2]);
  return pose;
}

}  // namespace xmate::client
