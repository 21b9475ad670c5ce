// SPDX-License-Identifier: Apache-2.0
// arm::RciArm (rci_arm.h): RobotState and the client's StateSample ring as ArmSamples, Control()
// in joint-position mode as runJointMotion, and the controller's six DO / DI.
#include "arm/rci_arm.h"

#include <stdexcept>

#include "client/connection.h"
#include "model/robot_spec.h"
#include "model/signal_names.h"

namespace xmate::arm {
namespace {

using RCI::robot::RobotState;

// From a RobotState or the client's StateSample (the same field names), and the TCP position.
template <class State>
ArmSample sampleOf(const State& s, const std::array<double, 3>& tcp_position) {
  ArmSample out;
  out.cycle = s.message_id;
  out.session = 1;
  out.q = s.q;
  out.q_command = s.q_c;
  out.tau = s.tau_m;
  out.wrench = s.tau_ext_in_base;
  out.tcp_position = tcp_position;
  return out;
}

ArmSample sampleOf(const RobotState& s) {
  return sampleOf(s, {s.toolTobase_pos_m[3], s.toolTobase_pos_m[7], s.toolTobase_pos_m[11]});
}

ArmState stateOf(const RobotState& s) {
  ArmState state;
  state.sample = sampleOf(s);
  state.tcp = s.toolTobase_pos_m;
  return state;
}

std::vector<std::string> names(bool output) {
  std::vector<std::string> list;
  for (int i = 0; i < model::kXmateSignalCount; ++i)
    list.push_back(output ? model::doName(model::RobotFamily::kXmate, i) : model::diName(model::RobotFamily::kXmate, i));
  return list;
}

void checkSignal(size_t index, const char* kind) {
  if (index >= size_t(model::kXmateSignalCount))
    throw std::runtime_error(std::string("the xMate has six digital ") + kind + "s (0 to 5); " + std::to_string(index) +
                             " is not one");
}

}  // namespace

ArmSample armSample(const client::StateSample& s) {
  ArmSample a = sampleOf(s, s.tcp_position);
  a.time = s.time;
  return a;
}

RciArm::RciArm(Robot& robot) : robot_(robot), spec_(&model::robotSpec(robot.type())) {}

Capabilities RciArm::capabilities() const {
  return Capability::kJointTorques | Capability::kExternalWrench | Capability::kPowerControl |
         Capability::kBuiltInGuiding | Capability::kControllerSafety | Capability::kDigitalIo |
         Capability::kCartesianMotion;
}

bool RciArm::latest(ArmState& out) const {
  RobotState s;
  if (!robot_.connection().latestState(s)) return false;
  out = stateOf(s);
  return true;
}

size_t RciArm::takeSamples(ArmSample* out, size_t max) {
  size_t n = 0;
  client::StateSample s;
  while (n < max && robot_.connection().samples().pop(s)) {
    out[n++] = armSample(s);
  }
  return n;
}

uint64_t RciArm::samplesDropped() const { return robot_.connection().samples().dropped(); }

void RciArm::runJointMotion(JointMotion& motion) {
  using CM = RCI::robot::StartMoveRequest::ControllerMode;
  using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
  robot_.startMove(CM::kJointPosition, MM::kJointPosition);
  bool first = true;
  robot_.Control(JointControl([&motion, &first](RobotState s) -> JointPositions {
    JointPositions command;
    ArmSample now = sampleOf(s);
    // The xMate takes the first command against the measured joints: the motion starts from them.
    if (first) now.q_command = s.q;
    first = false;
    const bool last = motion.command(now, command.q);
    command.motion_finished = last;
    return command;
  }));
}

void RciArm::runCartesianMotion(CartesianMotion& motion) {
  using CM = RCI::robot::StartMoveRequest::ControllerMode;
  using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
  robot_.startMove(CM::kCartesianPosition, MM::kCartesianPosition);
  robot_.Control(CartesianControl([&motion](RobotState s) -> CartesianPose {
    CartesianPose command;
    command.motion_finished = motion.command(stateOf(s), command.toolTobase_pos_c);
    command.psi_valid = false;  // keep the arm angle
    return command;
  }));
}

std::vector<std::string> RciArm::outputNames() const { return names(true); }
std::vector<std::string> RciArm::inputNames() const { return names(false); }

void RciArm::setOutput(size_t index, bool level) {
  checkSignal(index, "output");
  if (!robot_.setDO(RCI::robot::DOSIGNAL(uint8_t(index)), level))
    throw std::runtime_error("the controller refused the output change of " +
                             model::doName(model::RobotFamily::kXmate, int(index)));
}

bool RciArm::input(size_t index) {
  checkSignal(index, "input");
  return robot_.getDI(RCI::robot::DISIGNAL(uint8_t(index)));
}

}  // namespace xmate::arm
