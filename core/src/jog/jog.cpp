// SPDX-License-Identifier: Apache-2.0
// Jog command generators: ramped velocity along one axis, braking before limits, clean finish.
#include "jog/jog.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "net/clock.h"

namespace xmate::jog {
namespace {

RampLimits jointRamp(const model::RobotSpec& spec, int joint, double speed_fraction) {
  const double a = kJogJointAccelFraction * spec.ddq_max[joint];
  return {std::clamp(speed_fraction, 0.01, 1.0) * kJogJointSpeedFraction * spec.dq_max[joint], a,
          kJogJerkPerAccel * a};
}

RampLimits cartesianRamp(int axis, double speed_fraction) {
  const bool linear = axis < 3;
  const double a = linear ? kJogTranslationAccel : kJogRotationAccel;
  return {std::clamp(speed_fraction, 0.01, 1.0) * (linear ? kJogTranslationSpeed : kJogRotationSpeed), a,
          kJogJerkPerAccel * a};
}

}  // namespace

int elapsedCycles(uint64_t previous_id, uint64_t id) {
  if (id <= previous_id) return 1;
  return int(std::min<uint64_t>(id - previous_id, 20));
}

JointLimitsRad jogLimits(const model::RobotSpec& spec, bool soft_enabled,
                         const std::array<double, 7>& soft_lower_deg, const std::array<double, 7>& soft_upper_deg) {
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  JointLimitsRad l;
  for (int i = 0; i < spec.dof; ++i) {
    double lo = spec.q_min[i], hi = spec.q_max[i];
    if (soft_enabled) {
      lo = std::max(lo, soft_lower_deg[i] * kRad);
      hi = std::min(hi, soft_upper_deg[i] * kRad);
    }
    l.lower[i] = lo + kJogLimitMargin;
    l.upper[i] = hi - kJogLimitMargin;
  }
  return l;
}

JointLimitsRad withinCorrectionLimits(const JointLimitsRad& limits, const std::array<double, 6>& q_on,
                                      const rsi::AxisCorrectionLimits& correction) {
  arm::MotionBounds bounds;
  for (size_t i = 0; i < 6; ++i) {
    bounds.lower[i] = q_on[i] + correction.lower[i];
    bounds.upper[i] = q_on[i] + correction.upper[i];
  }
  return withinBounds(limits, bounds, 6);
}

JointLimitsRad withinBounds(const JointLimitsRad& limits, const arm::MotionBounds& bounds, int dof) {
  JointLimitsRad l = limits;
  for (size_t i = 0; i < size_t(std::clamp(dof, 0, 7)); ++i) {
    l.lower[i] = std::max(l.lower[i], bounds.lower[i] + kJogLimitMargin);
    l.upper[i] = std::min(l.upper[i], bounds.upper[i] - kJogLimitMargin);
  }
  return l;
}

JointJog::JointJog(const model::RobotSpec& spec, int joint, int direction, double speed_fraction,
                   const JointLimitsRad& limits, const JogFlags& flags, double cycle_s)
    : joint_(joint),
      direction_(direction >= 0 ? 1 : -1),
      limits_(limits),
      flags_(flags),
      ramp_(jointRamp(spec, joint, speed_fraction), cycle_s) {}

JointPositions JointJog::next(const RCI::robot::RobotState& state) {
  // At start the command equals the measured position (docs/robot_models.md, "Command rules").
  JointPositions command;
  const bool last = advance(state.message_id, state.q, command.q);
  if (last) return MotionFinished(command);
  return command;
}

bool JointJogMotion::command(const arm::ArmSample& now, std::array<double, 7>& q) {
  if (session_ != 0 && now.session != session_) {  // RSI restarted since the jog was planned: hold still
    session_changed_ = true;
    q = now.q_command;
    return true;
  }
  watch_();
  return jog_.advance(now.cycle, now.q_command, q);
}

bool JointJog::advance(uint64_t cycle, const std::array<double, 7>& start, std::array<double, 7>& q) {
  const int cycles = started_ ? elapsedCycles(last_id_, cycle) : 1;
  last_id_ = cycle;
  if (!started_) {
    q_ = start;
    started_ = true;
  }
  const bool go = flags_.held.load(std::memory_order_relaxed) && !flags_.stop.load(std::memory_order_relaxed);
  double target = go ? direction_ * ramp_.maxVelocity() : 0.0;
  if (go) {
    // Brake if, after one more cycle at full drive, stopping would carry the joint past its limit.
    JogRamp ahead = ramp_;
    const double moved = ahead.step(target);
    const double stop_at = q_[joint_] + moved + ahead.stoppingDistance();
    // Only toward the limit: a joint outside its range may always be jogged back in.
    if ((direction_ > 0 && stop_at > limits_.upper[joint_]) || (direction_ < 0 && stop_at < limits_.lower[joint_]))
      target = 0;
  }
  for (int c = 0; c < cycles; ++c) q_[joint_] += ramp_.step(target);
  q = q_;
  return !go && ramp_.atRest();
}

CartesianJog::CartesianJog(int axis, int direction, double speed_fraction, int dof, const JointLimitsRad& limits,
                           const JogFlags& flags)
    : axis_(axis),
      direction_(direction >= 0 ? 1 : -1),
      dof_(dof),
      limits_(limits),
      flags_(flags),
      ramp_(cartesianRamp(axis, speed_fraction)) {}

bool CartesianJog::jointsNearLimit(const std::array<double, 7>& q_c, const std::array<double, 7>& dq_c) const {
  // Joints keep roughly their present velocity while the TCP stops: a conservative extrapolation.
  const double horizon = ramp_.stoppingTime() + 0.002;
  for (size_t i = 0; i < size_t(dof_); ++i) {
    const double ahead = q_c[i] + dq_c[i] * horizon;
    if ((dq_c[i] > 0 && ahead > limits_.upper[i]) || (dq_c[i] < 0 && ahead < limits_.lower[i])) return true;
  }
  return false;
}

std::array<double, 16> CartesianJog::pose() const {
  std::array<double, 16> m = start_;
  const int k = axis_ % 3;
  if (axis_ < 3) {
    m[4 * k + 3] += travelled_;
    return m;
  }
  Eigen::Matrix3d r0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r0(i, j) = start_[4 * i + j];
  // Rotation about the base axis through the TCP.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(travelled_, Eigen::Vector3d::Unit(k)).toRotationMatrix() * r0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r(i, j);
  return m;
}

CartesianPose CartesianJog::next(const RCI::robot::RobotState& state) {
  CartesianPose command;
  const bool last = step(state.message_id, state.toolTobase_pos_m, state.q_c, state.dq_c, command.toolTobase_pos_c);
  command.psi_valid = false;  // keep the arm angle
  if (last) return MotionFinished(command);
  return command;
}

bool CartesianJog::advance(const arm::ArmState& now, std::array<double, 16>& pose) {
  const std::array<double, 7>& q_c = now.sample.q_command;
  std::array<double, 7> dq_c{};
  if (started_) {
    const double dt = elapsedCycles(last_id_, now.sample.cycle) * cycle_s_;
    for (size_t i = 0; i < 7; ++i) dq_c[i] = (q_c[i] - last_q_c_[i]) / dt;
  }
  last_q_c_ = q_c;
  return step(now.sample.cycle, now.tcp, q_c, dq_c, pose);
}

bool CartesianJog::step(uint64_t cycle, const std::array<double, 16>& tcp, const std::array<double, 7>& q_c,
                        const std::array<double, 7>& dq_c, std::array<double, 16>& out) {
  const int cycles = started_ ? elapsedCycles(last_id_, cycle) : 1;
  last_id_ = cycle;
  if (!started_) {
    start_ = tcp;  // at start the command equals the measured pose
    started_ = true;
  }
  const bool go = flags_.held.load(std::memory_order_relaxed) && !flags_.stop.load(std::memory_order_relaxed);
  double target = go ? direction_ * ramp_.maxVelocity() : 0.0;
  if (go && jointsNearLimit(q_c, dq_c)) target = 0;
  for (int c = 0; c < cycles; ++c) travelled_ += ramp_.step(target);
  out = pose();
  return !go && ramp_.atRest();
}

bool CartesianJogMotion::command(const arm::ArmState& now, std::array<double, 16>& pose) {
  watch_();
  return jog_.advance(now, pose);
}

guide::GuideParameters cartesianJogParameters(int axis, double speed_fraction) {
  guide::GuideParameters p;
  const bool translation = axis < 3;
  p.axes = translation ? guide::GuideAxes::kTranslation : guide::GuideAxes::kRotation;
  p.force_dead_band = 0;  // the push is exact: nothing to ignore
  p.torque_dead_band = 0;
  p.max_speed = std::max(1e-3, kJogTranslationSpeed * speed_fraction);
  p.max_angular_speed = std::max(1e-3, kJogRotationSpeed * speed_fraction);
  // The push settles at the capped speed; mass / inertia give about the jog's acceleration.
  p.mass = p.damping * p.max_speed * 1.5 / kJogTranslationAccel;
  p.inertia = p.rotational_damping * p.max_angular_speed * 1.5 / kJogRotationAccel;
  p.braking = translation ? kJogTranslationAccel : kJogRotationAccel;
  return p;
}

JogPush::JogPush(const arm::Arm& arm, int axis, int direction, const guide::GuideParameters& parameters)
    : arm_(arm), axis_(axis) {
  // 1.5 times what the damping needs at the top speed: the guide's cap holds the speed there.
  const double push = axis < 3 ? parameters.damping * parameters.max_speed * 1.5
                               : parameters.rotational_damping * parameters.max_angular_speed * 1.5;
  push_ = direction < 0 ? -push : push;
}

bool GuidedCartesianJogMotion::command(const arm::ArmSample& now, std::array<double, 7>& q) {
  watch_();
  if (!flags_.held.load(std::memory_order_relaxed) || flags_.stop.load(std::memory_order_relaxed)) guide_.requestStop();
  return guide_.command(now, q);
}

bool JogPush::read(std::array<double, 6>& wrench, int64_t& received_ns) const {
  received_ns = net::monotonicNs();  // always fresh: the guide never sees it silent
  wrench = {};
  if (!biased_) {
    biased_ = true;
    return true;
  }
  arm::ArmState state;
  if (!arm_.latest(state)) return true;
  // Base axis k in the flange frame: row k of R (R^T e_k), R the flange's rotation (row-major 4x4).
  const size_t k = size_t(axis_ % 3);
  const size_t offset = axis_ < 3 ? 0 : 3;
  for (size_t i = 0; i < 3; ++i) wrench[offset + i] = push_ * state.tcp[4 * k + i];
  return true;
}

}  // namespace xmate::jog
