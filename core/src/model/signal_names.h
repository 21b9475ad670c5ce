// SPDX-License-Identifier: Apache-2.0
// The digital signals of each robot family by name. An xMate: "DO0_0".."DO1_1" / "DI0_0".."DI1_1",
// index 0..5 (RCI's DOSIGNAL / DISIGNAL order). A KUKA: "$OUT[n]" / "$IN[n]", index n = 1..4096
// (the controller's numbers; over RSI, those the context wires to the PC). Any thread.
#pragma once

#include <string>

#include "model/robot_spec.h"

namespace xmate::model {

inline constexpr int kXmateSignalCount = 6;
inline constexpr int kKukaSignalCount = 4096;
std::string doName(RobotFamily family, int index);  // "?" for an index the family does not have
std::string diName(RobotFamily family, int index);
int doIndex(RobotFamily family, const std::string& name);  // -1 if not a signal of that family
int diIndex(RobotFamily family, const std::string& name);
// "DO0_0, DO0_1, ..." / "$OUT[1] to $OUT[4096]": the names doIndex / diIndex take, for messages.
std::string knownSignals(RobotFamily family, bool output);

}  // namespace xmate::model
