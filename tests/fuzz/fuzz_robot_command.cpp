// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: decodeRobotCommand on arbitrary datagrams (290 bytes, or the older 258 without
// dynamic_wall). It must never crash; an accepted datagram must encode back to the same fields.
#include <cstring>

#include "protocol/realtime_codec.h"

namespace {

// The 258-byte form lacks the 32 bytes of dynamic_wall that start at this offset in the 290 form.
constexpr size_t kDynamicWallOffset = 202;
constexpr size_t kDynamicWallSize = 32;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace xmate::protocol;
  RCI::robot::RobotCommand command;
  if (decodeRobotCommand(data, size, command) != DecodeStatus::kOk) return 0;
  RobotCommandBuffer again{};
  encodeRobotCommand(command, again);
  if (size == kRobotCommandSize) {
    if (std::memcmp(data, again.data(), size) != 0) __builtin_trap();
  } else if (size == kRobotCommandLegacySize) {
    const size_t tail = kRobotCommandLegacySize - kDynamicWallOffset;
    if (std::memcmp(data, again.data(), kDynamicWallOffset) != 0) __builtin_trap();
    if (std::memcmp(data + kDynamicWallOffset, again.data() + kDynamicWallOffset + kDynamicWallSize, tail) != 0)
      __builtin_trap();
    for (size_t i = 0; i < kDynamicWallSize; ++i)
      if (again[kDynamicWallOffset + i] != 0) __builtin_trap();
  } else {
    __builtin_trap();  // no other length may decode
  }
  return 0;
}
