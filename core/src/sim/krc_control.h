// SPDX-License-Identifier: Apache-2.0
// The simulated KRC's control port commands (rci-sim --rsi --control-port): the scene (a push on the
// arm, digital inputs, the override) and faults (answers dropped or late, <Rob> duplicated, RSI
// off for a while) while it runs, and its status -- the same line protocol as the simulated xMate's
// (control_lines.h, served by ControlPort). docs/rsi.md, "The simulated KRC".
#pragma once

#include <string>
#include <string_view>

#include "sim/krc.h"

namespace xmate::sim {

// Executes one command line against the KRC and returns the answer (without newline): "ok ..." or
// "error <what is wrong>; usage: ...". Never throws. Any thread (the Krc's scene and fault calls are).
std::string executeKrcControlLine(Krc& krc, std::string_view line);

// The command list, as "help" prints it (one line).
std::string krcControlHelp();

// "state=running last_stop=none session=1 ..." -- the status as one line of key=value pairs.
std::string formatKrcStatus(const KrcStatus& status);

}  // namespace xmate::sim
