// SPDX-License-Identifier: Apache-2.0
// Reading the controller's TCP responses for xmate::Robot: the one-byte status/value responses,
// their refusal texts, and the exceptions they turn into (CommandException for a refusal,
// ProtocolException for anything this library does not understand).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace xmate::client {

// The value byte of a {Command; uint8} response. Throws ProtocolException if the payload is not
// one (wrong size); call names the API call.
uint8_t byteValue(const char* call, const std::vector<uint8_t>& payload);

// Setter responses: returns if the status is success; throws CommandException("<call>: the
// controller refused: <status text><hint>") for a refusal and ProtocolException for an unknown status.
void requireSetterSuccess(const char* call, const std::vector<uint8_t>& payload, const char* hint = "");
// The same, with the hint for a kNotPossible refusal found only when it happens (refusal_cause.h).
using RefusalCause = std::function<std::string()>;
void requireSetterSuccess(const char* call, const std::vector<uint8_t>& payload, const RefusalCause& not_possible);

// StartMove: success and "motion started" are both accepted; not_possible gives the cause of a
// kNotPossible refusal.
void requireStartMoveSuccess(const std::vector<uint8_t>& payload, const RefusalCause& not_possible);
void requireStopMoveSuccess(const std::vector<uint8_t>& payload);
void requireRecoverySuccess(const std::vector<uint8_t>& payload);

// GetDIState: the level of the input; throws as above for a refusal.
bool digitalInputLevel(const std::vector<uint8_t>& payload);

}  // namespace xmate::client
