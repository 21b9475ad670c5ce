// SPDX-License-Identifier: Apache-2.0
// The executor's port for an arm::Arm of either family (an RciPort for an arm::RciArm, an RsiPort
// for an arm::RsiArm), chosen by the arm itself (arm::ArmVisitor), never by asking which it is.
#pragma once

#include <memory>

#include "teach/program.h"
#include "teach/robot_port.h"

namespace xmate::arm {
class Arm;
}

namespace xmate::teach {

// The port that runs `program` on `arm` (whose tool on RSI is the program's). The caller's thread;
// `arm` must outlive the port.
std::unique_ptr<RobotPort> armPort(arm::Arm& arm, const Program& program);

}  // namespace xmate::teach
