// SPDX-License-Identifier: Apache-2.0
// Recording helpers for the teach panel: a Target (q + TCP pose + arm angle) from a RobotState,
// and motion instructions built from taught targets.
#pragma once

#include <xmate/rci_types.h>

#include "teach/program.h"

namespace xmate::teach {

// The measured joints, TCP pose and arm angle of `state`; on 6-axis models q[6] is forced to 0
// and psi to 0.
Target targetFromState(const RCI::robot::RobotState& state, XmateType type);

Instruction moveJ(const Target& target, double speed, std::string name = {});
Instruction moveL(const Target& target, double speed, std::string name = {});
Instruction moveC(const Target& via, const Target& target, double speed, std::string name = {});

}  // namespace xmate::teach
