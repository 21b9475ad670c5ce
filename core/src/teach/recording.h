// SPDX-License-Identifier: Apache-2.0
// Recording helpers for the teach panel: a Target (q + TCP pose + arm angle) from a RobotState,
// and motion instructions built from taught targets.
#pragma once

#include <array>
#include <string>

#include <xmate/rci_types.h>

#include "arm/arm.h"
#include "teach/program.h"

namespace xmate::teach {

// The measured joints, TCP pose and arm angle of `state`; on 6-axis models q[6] is forced to 0
// and psi to 0.
Target targetFromState(const RCI::robot::RobotState& state, const model::RobotSpec& robot);
inline Target targetFromState(const RCI::robot::RobotState& state, XmateType type) {
  return targetFromState(state, model::robotSpec(type));
}

// The same from an arm of either family (arm::Arm::latest): the measured joints and TCP; the arm
// angle is 0 (only an xMate's RobotState reports it: use targetFromState there).
Target targetFromArm(const arm::ArmState& state, const model::RobotSpec& robot);

// The tool and payload a program is taught with. The first recording into an empty program without
// a recorded tool makes them the program's: `tool` (Robot::toolFrame()) if the measured TCP of
// `state` agrees with it, else the tool the measured TCP implies (another client or the pendant set
// it), and `load`. Later recordings need the robot's TCP to match the program's tool (toolMismatch,
// preflight.h). Returns "" when recording may go on, else the problem (toolMismatchText).
std::string adoptTool(Program& program, const std::array<double, 7>& q, const std::array<double, 16>& measured_tcp,
                      const std::array<double, 16>& tool, const Payload& load);
inline std::string adoptTool(Program& program, const RCI::robot::RobotState& state, const std::array<double, 16>& tool,
                             const Payload& load) {
  return adoptTool(program, state.q, state.toolTobase_pos_m, tool, load);
}

Instruction moveJ(const Target& target, double speed, std::string name = {});
Instruction moveL(const Target& target, double speed, std::string name = {});
Instruction moveC(const Target& via, const Target& target, double speed, std::string name = {});

}  // namespace xmate::teach
