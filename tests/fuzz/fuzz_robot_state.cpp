// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: decodeRobotState on arbitrary datagrams. It must never crash, and a datagram
// it accepts must encode back to exactly the same bytes (every field is read bit-exactly).
#include <cstring>

#include "protocol/realtime_codec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace xmate::protocol;
  RCI::robot::RobotState state;
  if (decodeRobotState(data, size, state) != DecodeStatus::kOk) return 0;
  RobotStateBuffer again{};
  encodeRobotState(state, again);
  if (size != again.size() || std::memcmp(data, again.data(), size) != 0) __builtin_trap();
  return 0;
}
