// SPDX-License-Identifier: Apache-2.0
// Names of the error bits (error_bits.h).
#include "sim/error_bits.h"

namespace xmate::sim {

const char* errorBitName(int bit) {
  static constexpr const char* kNames[kErrorBitCount] = {
      "kActualJointPositionLimitsViolation",
      "kActualCartesianPositionLimitsViolation",
      "kActualCartesianMotionGeneratorElbowLimitViolation",
      "kActualJointVelocityLimitsViolation",
      "kActualCartesianVelocityLimitsViolation",
      "kActualJointAccelerationLimitsViolation",
      "kActualCartesianAccelerationLimitsViolation",
      "kCommandJointPositionLimitsViolation",
      "kCommandCartesianPositionLimitsViolation",
      "kCommandCartesianMotionGeneratorElbowLimitViolation",
      "kCommandJointVelocityLimitsViolation",
      "kCommandCartesianVelocityLimitsViolation",
      "kCommandJointAccelerationLimitsViolation",
      "kCommandCartesianAccelerationLimitsViolation",
      "kCommandJointAccelerationDiscontinuity",
      "kCollision",
      "kCartesianPositionMotionGeneratorInvalidFrame",
      "kCommandTorqueDiscontinuity",
      "kCommandTorqueRangeViolation",
      "kInstabilityDetection",
  };
  return bit >= 0 && bit < kErrorBitCount ? kNames[bit] : "unknown error bit";
}

}  // namespace xmate::sim
