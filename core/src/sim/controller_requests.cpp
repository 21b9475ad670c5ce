// SPDX-License-Identifier: Apache-2.0
// The TCP command channel of the simulated controller: every request is decoded
// (protocol/tcp_codec.h), its values re-checked with the client's ranges
// (model/parameter_checks.h -> kInvalidArgument), refused when it makes no sense in the current
// state (kNotPossible and friends), and applied. Malformed and unknown requests get a response too.
#include <cmath>
#include <string>

#include "model/kinematics.h"
#include "model/parameter_checks.h"
#include "sim/controller_impl.h"
#include "sim/pose_math.h"
#include "sim/robot_model_dump.h"
#include "sim/safety.h"

namespace xmate::sim {
namespace {

using protocol::Command;
constexpr uint8_t kOk = static_cast<uint8_t>(protocol::SetterStatus::kSuccess);
constexpr uint8_t kNotPossible = static_cast<uint8_t>(protocol::SetterStatus::kNotPossible);
constexpr uint8_t kInvalid = static_cast<uint8_t>(protocol::SetterStatus::kInvalidArgument);

template <class Request>
bool decoded(const uint8_t* p, size_t n, Request& request) {
  return protocol::decodePayload(p, n, request) == protocol::DecodeStatus::kOk;
}

std::string malformed(Command command, size_t n) {
  return std::string(protocol::commandName(command)) + ": malformed request (" + std::to_string(n) +
         " payload bytes, or a bool that is not 0/1); check the client's protocol version";
}

protocol::Frame byteResponse(uint32_t sequence, Command command, uint8_t value) {
  return protocol::encodeFrame(sequence, protocol::ByteResponse{command, value});
}

uint32_t commandCode(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

Eigen::Vector3d toVector3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

}  // namespace

uint8_t Controller::Impl::refuse(uint8_t status, std::string reason) {
  last_refusal = std::move(reason);
  return status;
}

bool Controller::Impl::busyForModelChange(const char* call) {
  if (activity == Activity::kHold) return false;
  refuse(kNotPossible, std::string(call) +
                           ": not possible while a motion or hand guiding is running; call it before "
                           "startMove/startDrag (tool, load, frames and limits must not change mid-motion)");
  return true;
}

protocol::Frame Controller::Impl::handleRequest(uint32_t sequence, const uint8_t* p, size_t n) {
  if (p == nullptr || n < 4) {
    refuse(kInvalid, "request of " + std::to_string(p ? n : 0) + " bytes is too short to hold a command code");
    return byteResponse(sequence, Command::kInvalid, kInvalid);
  }
  const uint32_t code = commandCode(p);
  if (!protocol::isKnownCommand(code)) {
    refuse(kNotPossible, "unknown command code " + std::to_string(code) + " (this controller knows 0..24)");
    return byteResponse(sequence, static_cast<Command>(code), kNotPossible);
  }
  const auto command = static_cast<Command>(code);
  protocol::EmptyRequest empty{command};
  switch (command) {
    case Command::kConnect: {
      protocol::ConnectRequest r;
      if (!decoded(p, n, r)) return byteResponse(sequence, command, refuse(1, malformed(command, n)));
      if (config.reject_connect_as_incompatible)
        return byteResponse(sequence, command, refuse(1, "Connect: configured to answer kIncompatibleLibraryVersion"));
      return byteResponse(sequence, command, kOk);
    }
    case Command::kGetMotorState:
      if (!decoded(p, n, empty)) return byteResponse(sequence, Command::kInvalid, refuse(kInvalid, malformed(command, n)));
      return byteResponse(sequence, command, motors_on ? 1 : 0);
    case Command::kGetSafetyStopState:  // wire: 0 none, 1 ESTOP, 2 GSTOP
      if (!decoded(p, n, empty)) return byteResponse(sequence, Command::kInvalid, refuse(kInvalid, malformed(command, n)));
      return byteResponse(sequence, command, static_cast<uint8_t>(safetyStop() - 1));
    case Command::kGetDIState: {
      protocol::GetDIStateRequest r;
      protocol::GetDIStateResponse response;
      if (!decoded(p, n, r)) {
        response.status = refuse(kInvalid, malformed(command, n));
      } else if (r.signal > 5) {
        response.status = refuse(kInvalid, "getDI: signal " + std::to_string(r.signal) + " is outside 0..5 (DI0_0..DI1_1)");
      } else {
        response.state = digital_in[r.signal];
      }
      return protocol::encodeFrame(sequence, response);
    }
    case Command::kLoadRobotModel: {
      if (!decoded(p, n, empty)) {
        protocol::LoadRobotModelResponse response;
        response.status = refuse(kInvalid, malformed(command, n));
        return protocol::encodeFrame(sequence, response);
      }
      return protocol::encodeFrame(sequence, robotModelResponse(spec, chain, params, settings));
    }
    case Command::kStartMove: return byteResponse(sequence, command, startMove(p, n));
    case Command::kStopMove:
      if (!decoded(p, n, empty)) return byteResponse(sequence, command, refuse(1, malformed(command, n)));
      return byteResponse(sequence, command, stopMove());
    case Command::kSetMotorPower: return byteResponse(sequence, command, setMotorPower(p, n));
    case Command::kSetCartesianLimit: return byteResponse(sequence, command, setCartesianLimit(p, n));
    case Command::kSetJointLimit: return byteResponse(sequence, command, setJointLimit(p, n));
    case Command::kSetCollisionBehavior: return byteResponse(sequence, command, setCollisionBehavior(p, n));
    case Command::kSetJointImpedance: return byteResponse(sequence, command, setJointImpedance(p, n));
    case Command::kSetCartesianImpedance: return byteResponse(sequence, command, setCartesianImpedance(p, n));
    case Command::kSetCoor: return byteResponse(sequence, command, setCoor(p, n));
    case Command::kSetLoad: return byteResponse(sequence, command, setLoad(p, n));
    case Command::kSetCartImpDesiredTau: return byteResponse(sequence, command, setCartImpDesiredTau(p, n));
    case Command::kSetFilters: return byteResponse(sequence, command, setFilters(p, n));
    case Command::kSetTorqueFilterCutOffFrequency:
      return byteResponse(sequence, command, setTorqueFilterCutOffFrequency(p, n));
    case Command::kAutomaticErrorRecovery: return byteResponse(sequence, command, automaticErrorRecovery(p, n));
    case Command::kSetFcCoor: return byteResponse(sequence, command, setFcCoor(p, n));
    case Command::kEnableVirtualGuide: return byteResponse(sequence, command, enableVirtualGuide(p, n));
    case Command::kSetDO: return byteResponse(sequence, command, setDO(p, n));
    case Command::kStartDrag: return byteResponse(sequence, command, startDrag(p, n));
    case Command::kStopDrag: return byteResponse(sequence, command, stopDrag(p, n));
    case Command::kRebootRobot: return byteResponse(sequence, command, rebootRobot(p, n));
    case Command::kInvalid: break;
  }
  return byteResponse(sequence, Command::kInvalid, refuse(kInvalid, "invalid command code"));
}

uint8_t Controller::Impl::setMotorPower(const uint8_t* p, size_t n) {
  protocol::SetMotorPowerRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetMotorPower, n));
  if (auto e = model::checkMotorPower(r.state); !e.empty()) return refuse(kInvalid, e);
  if (r.state == 0) {
    powerOff();
    return kOk;
  }
  if (estop) return refuse(kNotPossible, "setMotorPower(1): the emergency stop is pressed; release it first");
  if (reboot_requested) return refuse(kNotPossible, "setMotorPower(1): the controller is rebooting");
  powerOn();
  return kOk;
}

uint8_t Controller::Impl::setCartesianLimit(const uint8_t* p, size_t n) {
  protocol::SetCartesianLimitRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetCartesianLimit, n));
  if (auto e = model::checkCartesianLimit(r.size, r.frame); !e.empty()) return refuse(kInvalid, e);
  if (busyForModelChange("setCartesianLimit")) return kNotPossible;
  SafetyBox box;
  box.active = r.active;
  box.size = toVector3(r.size);
  box.frame = toIsometry(r.frame);
  if (box.active && motors_on && !insideSafetyBox(box, meas.tcp.translation()))
    return refuse(kNotPossible,
                  "setCartesianLimit: the TCP is outside the requested box; move the TCP inside first or enlarge "
                  "the box");
  settings.safety_box = box;
  box_allowance.reset(box, meas.tcp.translation());
  return kOk;
}

uint8_t Controller::Impl::setJointLimit(const uint8_t* p, size_t n) {
  protocol::SetJointLimitRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetJointLimit, n));
  if (auto e = model::checkSoftLimits(spec, r.upper, r.lower); !e.empty()) return refuse(kInvalid, e);
  if (busyForModelChange("setJointLimit")) return kNotPossible;
  constexpr double kRad = 3.14159265358979323846 / 180.0;
  const JointVector upper = toJointVector(r.upper, spec.dof) * kRad;
  const JointVector lower = toJointVector(r.lower, spec.dof) * kRad;
  settings.soft_upper = upper;
  settings.soft_lower = lower;
  settings.auto_limit = r.auto_limit;
  joint_allowance.reset(plant.q, lower, upper, spec.dof);
  // Limits that leave a joint outside are accepted, and the joint is reported beyond its limit at
  // once (bit 0), as a measured violation: after recovery it may be moved back in, not further out.
  for (int i = 0; i < spec.dof; ++i)
    if (plant.q[i] < lower[i] || plant.q[i] > upper[i]) {
      ErrorBits bits{};
      raise(bits, kActualJointPositionLimitsViolation);
      raiseErrors(bits);
      break;
    }
  return kOk;
}

uint8_t Controller::Impl::setCollisionBehavior(const uint8_t* p, size_t n) {
  protocol::SetCollisionBehaviorRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetCollisionBehavior, n));
  if (auto e = model::checkCollisionThresholds(spec, r.thresholds); !e.empty()) return refuse(kInvalid, e);
  settings.collision_thresholds = toJointVector(r.thresholds, spec.dof);
  return kOk;
}

uint8_t Controller::Impl::setJointImpedance(const uint8_t* p, size_t n) {
  protocol::SetJointImpedanceRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetJointImpedance, n));
  if (auto e = model::checkJointImpedance(spec, r.stiffness); !e.empty()) return refuse(kInvalid, e);
  settings.joint_stiffness = toJointVector(r.stiffness, spec.dof);
  return kOk;
}

uint8_t Controller::Impl::setCartesianImpedance(const uint8_t* p, size_t n) {
  protocol::SetCartesianImpedanceRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetCartesianImpedance, n));
  if (auto e = model::checkCartesianImpedance(r.stiffness); !e.empty()) return refuse(kInvalid, e);
  settings.cartesian_stiffness = toVector6(r.stiffness);
  return kOk;
}

uint8_t Controller::Impl::setCoor(const uint8_t* p, size_t n) {
  protocol::SetCoorRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetCoor, n));
  if (auto e = model::checkToolFrame(r.flange_to_tool); !e.empty()) return refuse(kInvalid, e);
  if (busyForModelChange("setCoor")) return kNotPossible;
  settings.tool = toIsometry(r.flange_to_tool);
  model::setTool(arm, settings.tool);
  model::setTool(plant_arm, settings.tool);
  meas.tcp = model::tcpPose(arm, plant.q);
  return kOk;
}

uint8_t Controller::Impl::setLoad(const uint8_t* p, size_t n) {
  protocol::SetLoadRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetLoad, n));
  if (auto e = model::checkLoad(spec, r.mass, r.center, r.inertia); !e.empty()) return refuse(kInvalid, e);
  if (busyForModelChange("setLoad")) return kNotPossible;
  model::Payload load;
  load.mass = r.mass;
  load.com = toVector3(r.center);
  load.inertia = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r.inertia.data());
  model::setPayload(arm, load);
  if (plant_follows_load) model::setPayload(plant_arm, load);
  settings.load = load;
  return kOk;
}

uint8_t Controller::Impl::setCartImpDesiredTau(const uint8_t* p, size_t n) {
  protocol::SetCartImpDesiredTauRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetCartImpDesiredTau, n));
  if (auto e = model::checkDesiredWrench(r.tau); !e.empty()) return refuse(kInvalid, e);
  settings.desired_wrench = toVector6(r.tau);
  return kOk;
}

uint8_t Controller::Impl::setFilters(const uint8_t* p, size_t n) {
  protocol::SetFiltersRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetFilters, n));
  if (auto e = model::checkFilters(r.joint_hz, r.cartesian_hz, r.torque_hz); !e.empty()) return refuse(kInvalid, e);
  settings.joint_filter_hz = r.joint_hz;
  settings.cartesian_filter_hz = r.cartesian_hz;
  settings.torque_filter_hz = r.torque_hz;
  return kOk;
}

uint8_t Controller::Impl::setTorqueFilterCutOffFrequency(const uint8_t* p, size_t n) {
  protocol::SetTorqueFilterCutOffFrequencyRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetTorqueFilterCutOffFrequency, n));
  if (!std::isfinite(r.hz) || r.hz < model::kFilterMinHz || r.hz > model::kFilterMaxHz)
    return refuse(kInvalid, "setTorqueFilterCutOffFrequency: " + std::to_string(r.hz) + " Hz is outside [" +
                                std::to_string(model::kFilterMinHz) + ", " + std::to_string(model::kFilterMaxHz) +
                                "] Hz");
  settings.measured_torque_filter_hz = r.hz;
  return kOk;
}

uint8_t Controller::Impl::automaticErrorRecovery(const uint8_t* p, size_t n) {
  using protocol::ErrorRecoveryStatus;
  protocol::EmptyRequest r{Command::kAutomaticErrorRecovery};
  if (!decoded(p, n, r))
    return refuse(static_cast<uint8_t>(ErrorRecoveryStatus::kNotPossible), malformed(Command::kAutomaticErrorRecovery, n));
  if (estop)
    return refuse(static_cast<uint8_t>(ErrorRecoveryStatus::kManualRecoveryRequired),
                  "automaticErrorRecovery: the emergency stop is pressed; release it, then recover");
  if (hasErrors()) {
    errors.fill(false);
    recovery_cycles_left = kRecoveryCycles;
  }
  return static_cast<uint8_t>(ErrorRecoveryStatus::kSuccess);
}

uint8_t Controller::Impl::setFcCoor(const uint8_t* p, size_t n) {
  protocol::SetFcCoorRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetFcCoor, n));
  if (auto e = model::checkForceFrame(r.frame, int(r.type) + 1); !e.empty()) return refuse(kInvalid, e);
  if (busyForModelChange("setFcCoor")) return kNotPossible;
  settings.force_frame = toIsometry(r.frame);
  settings.force_frame_type = r.type;
  return kOk;
}

uint8_t Controller::Impl::enableVirtualGuide(const uint8_t* p, size_t n) {
  protocol::EnableVirtualGuideRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kEnableVirtualGuide, n));
  for (size_t i = 0; i < 6; ++i) {
    const double k = r.stiffness[i], max = model::kCartesianStiffnessMax[i];
    if (!std::isfinite(k) || k < 0 || k > max)
      return refuse(kInvalid, "enableVirtualGuide: stiffness[" + std::to_string(i) + "] = " + std::to_string(k) +
                                  " is outside [0, " + std::to_string(max) + "] " + (i < 3 ? "N/m" : "Nm/rad"));
  }
  settings.virtual_guide_enabled = r.enable;
  settings.virtual_guide_stiffness = toVector6(r.stiffness);
  return kOk;
}

uint8_t Controller::Impl::setDO(const uint8_t* p, size_t n) {
  protocol::SetDORequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kSetDO, n));
  if (r.signal > 5)
    return refuse(kInvalid, "setDO: signal " + std::to_string(r.signal) + " is outside 0..5 (DO0_0..DO1_1)");
  digital_out[r.signal] = r.state;
  updateDigitalInputs();
  return kOk;
}

uint8_t Controller::Impl::startDrag(const uint8_t* p, size_t n) {
  protocol::StartDragRequest r;
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kStartDrag, n));
  if (auto e = model::checkDrag(int(r.space) + 1, int(r.type) + 1); !e.empty()) return refuse(kInvalid, e);
  if (estop) return refuse(kNotPossible, "startDrag: the emergency stop is pressed");
  if (guard_stop) return refuse(kNotPossible, "startDrag: the guard stop is active");
  if (hasErrors()) return refuse(kNotPossible, "startDrag: error bits are set; call automaticErrorRecovery first");
  if (!motors_on) return refuse(kNotPossible, "startDrag: the motors are off; call setMotorPower(1) first");
  if (activity == Activity::kMotion) return refuse(kNotPossible, "startDrag: a motion is running; stop it first");
  if (ref.ramp.active) return refuse(kNotPossible, "startDrag: the robot is still stopping");
  if (reboot_requested) return refuse(kNotPossible, "startDrag: the controller is rebooting");
  startGuiding(r.space, r.type);
  return kOk;
}

uint8_t Controller::Impl::stopDrag(const uint8_t* p, size_t n) {
  protocol::EmptyRequest r{Command::kStopDrag};
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kStopDrag, n));
  if (activity == Activity::kDrag) stopFromMeasured();
  return kOk;
}

uint8_t Controller::Impl::rebootRobot(const uint8_t* p, size_t n) {
  protocol::EmptyRequest r{Command::kRebootRobot};
  if (!decoded(p, n, r)) return refuse(kInvalid, malformed(Command::kRebootRobot, n));
  reboot_requested = true;
  powerOff();
  return kOk;
}

}  // namespace xmate::sim
