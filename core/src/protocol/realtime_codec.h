// SPDX-License-Identifier: Apache-2.0
// The two UDP datagrams of the 1 kHz exchange (docs/protocol.md, "Real-time datagrams"):
// RobotState (controller -> client, 1247 bytes) and RobotCommand (client -> controller, 290 bytes;
// the older 258-byte form without dynamic_wall is accepted on receive). Allocation-free.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <xmate/rci_types.h>

namespace xmate::protocol {

inline constexpr size_t kRobotStateSize = 1247;
inline constexpr size_t kRobotCommandSize = 290;
inline constexpr size_t kRobotCommandLegacySize = 258;

// Offsets pinned by the wire description (checked in tests/protocol).
inline constexpr size_t kRobotStateErrorsOffset = 1216;
inline constexpr size_t kRobotStateSuccessRateOffset = 1236;
inline constexpr size_t kRobotStateModesOffset = 1244;

enum class DecodeStatus {
  kOk,
  kWrongLength,  // datagram is not one of the accepted sizes (usually a version mismatch)
  kBadValue,     // a bool that is not 0/1 or an enum out of range (corrupted datagram)
};
const char* toString(DecodeStatus status);

using RobotStateBuffer = std::array<uint8_t, kRobotStateSize>;
using RobotCommandBuffer = std::array<uint8_t, kRobotCommandSize>;

void encodeRobotState(const RCI::robot::RobotState& state, RobotStateBuffer& out);
DecodeStatus decodeRobotState(const uint8_t* data, size_t size, RCI::robot::RobotState& out);

void encodeRobotCommand(const RCI::robot::RobotCommand& command, RobotCommandBuffer& out);
DecodeStatus decodeRobotCommand(const uint8_t* data, size_t size, RCI::robot::RobotCommand& out);

}  // namespace xmate::protocol
