// SPDX-License-Identifier: Apache-2.0
// The 20 error bits of RobotState::errors (docs/simulator_controller.md) by name, and small helpers to set and test
// them. The simulated controller sets a bit when it detects the violation; bits stay set until
// AutomaticErrorRecovery.
#pragma once

#include <array>
#include <cstddef>

namespace xmate::sim {

enum ErrorBit : int {
  kActualJointPositionLimitsViolation = 0,
  kActualCartesianPositionLimitsViolation = 1,
  kActualCartesianMotionGeneratorElbowLimitViolation = 2,
  kActualJointVelocityLimitsViolation = 3,
  kActualCartesianVelocityLimitsViolation = 4,
  kActualJointAccelerationLimitsViolation = 5,
  kActualCartesianAccelerationLimitsViolation = 6,
  kCommandJointPositionLimitsViolation = 7,
  kCommandCartesianPositionLimitsViolation = 8,
  kCommandCartesianMotionGeneratorElbowLimitViolation = 9,
  kCommandJointVelocityLimitsViolation = 10,
  kCommandCartesianVelocityLimitsViolation = 11,
  kCommandJointAccelerationLimitsViolation = 12,
  kCommandCartesianAccelerationLimitsViolation = 13,
  kCommandJointAccelerationDiscontinuity = 14,
  kCollision = 15,
  kCartesianPositionMotionGeneratorInvalidFrame = 16,
  kCommandTorqueDiscontinuity = 17,
  kCommandTorqueRangeViolation = 18,
  kInstabilityDetection = 19,
};
inline constexpr int kErrorBitCount = 20;

using ErrorBits = std::array<bool, kErrorBitCount>;

inline void raise(ErrorBits& bits, ErrorBit bit) { bits[static_cast<std::size_t>(bit)] = true; }

inline bool anyError(const ErrorBits& bits) {
  for (bool b : bits)
    if (b) return true;
  return false;
}

// bits |= more
inline void merge(ErrorBits& bits, const ErrorBits& more) {
  for (std::size_t i = 0; i < bits.size(); ++i) bits[i] = bits[i] || more[i];
}

// English name of a bit ("kCollision"), for messages and logs.
const char* errorBitName(int bit);

}  // namespace xmate::sim
