// SPDX-License-Identifier: Apache-2.0
// ArmChannels (arm_channels.h): arm sample to buffer channels, with the velocity by differences.
#include "plots/arm_channels.h"

#include <limits>

namespace rci::ui::plots {

namespace {

void put(ChannelValues& out, Signal signal, int index, double value) {
  out[static_cast<std::size_t>(channelOf(signal, index))] = value;
}

}  // namespace

void ArmChannels::map(const xmate::arm::ArmSample& s, const ArmExtras& extras, ChannelValues& out) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double dt = 0;
  if (has_previous_ && s.session == previous_session_) {
    if (s.cycle > previous_cycle_ && cycle_s_ > 0)
      dt = static_cast<double>(s.cycle - previous_cycle_) * cycle_s_;
    else if (s.time > previous_time_)
      dt = s.time - previous_time_;
  }
  for (int j = 0; j < kJointCount; ++j) {
    const auto k = static_cast<std::size_t>(j);
    put(out, Signal::kAxisActual, j, s.q[k]);
    put(out, Signal::kAxisSetPoint, j, s.q_command[k]);
    put(out, Signal::kAxisVelocity, j, dt > 0 ? (s.q[k] - previous_q_[k]) / dt : kNaN);
    put(out, Signal::kGearTorque, j, s.gear_torque[k]);
    put(out, Signal::kMotorCurrent, j, s.motor_current[k]);
  }
  for (int i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    put(out, Signal::kSensorForce, i, extras.force_valid ? extras.force[k] : kNaN);
    put(out, Signal::kSensorTorque, i, extras.force_valid ? extras.force[k + 3] : kNaN);
    put(out, Signal::kTcpActual, i, s.tcp_position[k]);
    put(out, Signal::kTcpSetPoint, i, s.tcp_position_command[k]);
  }
  put(out, Signal::kLateAnswers, 0, extras.late_answers);
  has_previous_ = true;
  previous_session_ = s.session;
  previous_cycle_ = s.cycle;
  previous_time_ = s.time;
  previous_q_ = s.q;
}

}  // namespace rci::ui::plots
