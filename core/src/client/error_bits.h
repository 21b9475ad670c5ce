// SPDX-License-Identifier: Apache-2.0
// The 20 error bits of RobotState::errors (docs/error_bits.md; which rule of the simulator sets
// each: docs/simulator_controller.md, "Command rules and the error bits"): their names, what they
// mean, what to do, and the sentence a ControlException carries when the controller sets some of
// them; robot mode names.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <xmate/rci_types.h>

namespace xmate::client {

inline constexpr int kErrorBitCount = 20;

// "kCollision" for 15; "unknown" outside 0..19.
const char* errorBitName(int bit);
// One line: what the bit reports ("commanded joint velocity over the limit").
const char* errorBitMeaning(int bit);
// What the user should do about it (the manual's remedy text).
const char* errorBitRemedy(int bit);

// Bit i of the result is errors[i].
uint32_t errorMask(const std::array<bool, kErrorBitCount>& errors);
bool anyError(const std::array<bool, kErrorBitCount>& errors);

// "10 kCommandJointVelocityLimitsViolation (commanded joint velocity over the limit), 15 kCollision (...)"
// followed by the distinct remedies of the set bits. Empty when no bit is set.
std::string describeErrors(const std::array<bool, kErrorBitCount>& errors);

// "kMove", "kReflex", ... (RobotState::robot_mode).
const char* robotModeName(RCI::robot::RobotMode mode);

}  // namespace xmate::client
