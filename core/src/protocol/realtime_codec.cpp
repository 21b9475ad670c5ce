// SPDX-License-Identifier: Apache-2.0
// Field order of RobotState and RobotCommand on the wire; see realtime_codec.h.
#include "protocol/realtime_codec.h"

#include "protocol/byte_io.h"

namespace xmate::protocol {

using RCI::robot::RobotCommand;
using RCI::robot::RobotState;

const char* toString(DecodeStatus status) {
  switch (status) {
    case DecodeStatus::kOk: return "ok";
    case DecodeStatus::kWrongLength: return "wrong datagram length (client and controller versions differ?)";
    case DecodeStatus::kBadValue: return "invalid field value (corrupted datagram)";
  }
  return "unknown";
}

void encodeRobotState(const RobotState& s, RobotStateBuffer& out) {
  ByteWriter w(out.data(), out.size());
  w.be64(s.message_id);
  w.f64s(s.q); w.f64s(s.q_c); w.f64s(s.dq_m); w.f64s(s.dq_c); w.f64s(s.ddq_c);
  w.f64s(s.toolTobase_pos_m); w.f64s(s.toolTobase_pos_c);
  w.f64s(s.toolTobase_vel_c); w.f64s(s.toolTobase_acc_c);
  w.f64(s.psi_m); w.f64(s.psi_c); w.f64(s.psi_vel_c); w.f64(s.psi_acc_c);
  w.f64s(s.tau_m); w.f64s(s.tau_m_filtered); w.f64s(s.tau_c); w.f64s(s.tau_vel_c);
  w.f64s(s.tau_ext_in_base); w.f64s(s.tau_ext_in_stiff);
  w.f64s(s.theta_m); w.f64s(s.theta_vel_m); w.f64s(s.motor_tau); w.f64s(s.motor_tau_filtered);
  w.bools(s.errors);
  w.f64(s.control_command_success_rate);
  w.u8(static_cast<uint8_t>(s.motion_generator_mode));
  w.u8(static_cast<uint8_t>(s.controller_mode));
  w.u8(static_cast<uint8_t>(s.robot_mode));
}

DecodeStatus decodeRobotState(const uint8_t* data, size_t size, RobotState& s) {
  if (size != kRobotStateSize) return DecodeStatus::kWrongLength;
  ByteReader r(data, size);
  s.message_id = r.be64();
  r.f64s(s.q); r.f64s(s.q_c); r.f64s(s.dq_m); r.f64s(s.dq_c); r.f64s(s.ddq_c);
  r.f64s(s.toolTobase_pos_m); r.f64s(s.toolTobase_pos_c);
  r.f64s(s.toolTobase_vel_c); r.f64s(s.toolTobase_acc_c);
  s.psi_m = r.f64(); s.psi_c = r.f64(); s.psi_vel_c = r.f64(); s.psi_acc_c = r.f64();
  r.f64s(s.tau_m); r.f64s(s.tau_m_filtered); r.f64s(s.tau_c); r.f64s(s.tau_vel_c);
  r.f64s(s.tau_ext_in_base); r.f64s(s.tau_ext_in_stiff);
  r.f64s(s.theta_m); r.f64s(s.theta_vel_m); r.f64s(s.motor_tau); r.f64s(s.motor_tau_filtered);
  r.bools(s.errors);
  s.control_command_success_rate = r.f64();
  s.motion_generator_mode = r.enum8<RCI::robot::MotionGeneratorMode>(4);
  s.controller_mode = r.enum8<RCI::robot::ControllerMode>(5);
  s.robot_mode = r.enum8<RCI::robot::RobotMode>(6);
  return r.ok() && r.atEnd() ? DecodeStatus::kOk : DecodeStatus::kBadValue;
}

void encodeRobotCommand(const RobotCommand& c, RobotCommandBuffer& out) {
  ByteWriter w(out.data(), out.size());
  w.be64(c.message_id);
  w.f64s(c.motion.q_c);
  w.f64s(c.motion.toolTobase_pos_c);
  w.boolean(c.motion.psi_valid);
  w.f64(c.motion.psi_c);
  w.boolean(c.motion.motion_generation_finished);
  w.f64s(c.motion.dynamic_wall);
  w.f64s(c.torque.tau_c);
}

DecodeStatus decodeRobotCommand(const uint8_t* data, size_t size, RobotCommand& c) {
  if (size != kRobotCommandSize && size != kRobotCommandLegacySize) return DecodeStatus::kWrongLength;
  ByteReader r(data, size);
  c.message_id = r.be64();
  r.f64s(c.motion.q_c);
  r.f64s(c.motion.toolTobase_pos_c);
  c.motion.psi_valid = r.boolean();
  c.motion.psi_c = r.f64();
  c.motion.motion_generation_finished = r.boolean();
  if (size == kRobotCommandSize)
    r.f64s(c.motion.dynamic_wall);
  else
    c.motion.dynamic_wall = {};
  r.f64s(c.torque.tau_c);
  return r.ok() && r.atEnd() ? DecodeStatus::kOk : DecodeStatus::kBadValue;
}

}  // namespace xmate::protocol
