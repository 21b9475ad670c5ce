// SPDX-License-Identifier: Apache-2.0
// Names, meanings and remedies of the controller's error bits (docs/error_bits.md).
#include "client/error_bits.h"

namespace xmate::client {
namespace {

struct ErrorBitInfo {
  const char* name;
  const char* meaning;
  int remedy;  // index into kRemedies
};

constexpr const char* kRemedies[] = {
    // 0: trajectory rules (bits 0-14, 17, 18)
    "check that the planned trajectory is continuous and differentiable and within the limits of the "
    "model (docs/error_bits.md), filter it if needed (setFilters)",
    // 1: collision
    "a collision was detected and the motors were powered off: if there was no contact, raise the thresholds "
    "(setCollisionBehavior) or correct the payload (setLoad); then automaticErrorRecovery() and setMotorPower(1)",
    // 2: singular frame
    "the commanded pose is singular or not reachable: plan the Cartesian motion away from singular poses "
    "(stretched arm, aligned wrist axes)",
    // 3: instability
    "commands were lost in a row (check the real-time setup with `rci-cli doctor` and the network), or a "
    "servo fault or an emergency stop occurred",
};

constexpr ErrorBitInfo kBits[kErrorBitCount] = {
    {"kActualJointPositionLimitsViolation", "measured joint position over the limit", 0},
    {"kActualCartesianPositionLimitsViolation", "measured TCP pose over the limit (e.g. outside the safety box)", 0},
    {"kActualCartesianMotionGeneratorElbowLimitViolation", "measured arm angle over the limit", 0},
    {"kActualJointVelocityLimitsViolation", "measured joint velocity over the limit", 0},
    {"kActualCartesianVelocityLimitsViolation", "measured TCP velocity over the limit", 0},
    {"kActualJointAccelerationLimitsViolation", "measured joint acceleration over the limit", 0},
    {"kActualCartesianAccelerationLimitsViolation", "measured TCP acceleration over the limit", 0},
    {"kCommandJointPositionLimitsViolation", "commanded joint position over the (soft) limit", 0},
    {"kCommandCartesianPositionLimitsViolation", "commanded TCP pose outside the workspace", 0},
    {"kCommandCartesianMotionGeneratorElbowLimitViolation", "commanded arm angle over the limit", 0},
    {"kCommandJointVelocityLimitsViolation", "commanded joint velocity over the limit", 0},
    {"kCommandCartesianVelocityLimitsViolation", "commanded TCP velocity over the limit", 0},
    {"kCommandJointAccelerationLimitsViolation", "commanded joint acceleration over the limit", 0},
    {"kCommandCartesianAccelerationLimitsViolation", "commanded TCP acceleration over the limit", 0},
    {"kCommandJointAccelerationDiscontinuity", "commanded joint acceleration jumps (jerk over the limit)", 0},
    {"kCollision", "collision detected", 1},
    {"kCartesianPositionMotionGeneratorInvalidFrame", "singular pose during Cartesian motion", 2},
    {"kCommandTorqueDiscontinuity", "commanded torque changes too fast", 0},
    {"kCommandTorqueRangeViolation", "commanded torque over the limit", 0},
    {"kInstabilityDetection", "too many consecutive commands lost, servo fault or emergency stop", 3},
};

}  // namespace

const char* errorBitName(int bit) { return bit >= 0 && bit < kErrorBitCount ? kBits[bit].name : "unknown"; }

const char* errorBitMeaning(int bit) {
  return bit >= 0 && bit < kErrorBitCount ? kBits[bit].meaning : "unknown error bit";
}

const char* errorBitRemedy(int bit) {
  return bit >= 0 && bit < kErrorBitCount ? kRemedies[kBits[bit].remedy] : "";
}

uint32_t errorMask(const std::array<bool, kErrorBitCount>& errors) {
  uint32_t mask = 0;
  for (int i = 0; i < kErrorBitCount; ++i)
    if (errors[i]) mask |= uint32_t(1) << i;
  return mask;
}

bool anyError(const std::array<bool, kErrorBitCount>& errors) { return errorMask(errors) != 0; }

std::string describeErrors(const std::array<bool, kErrorBitCount>& errors) {
  std::string bits;
  bool remedy_used[std::size(kRemedies)] = {};
  for (int i = 0; i < kErrorBitCount; ++i) {
    if (!errors[i]) continue;
    if (!bits.empty()) bits += ", ";
    bits += std::to_string(i) + " " + kBits[i].name + " (" + kBits[i].meaning + ")";
    remedy_used[kBits[i].remedy] = true;
  }
  if (bits.empty()) return bits;
  std::string remedies;
  for (size_t r = 0; r < std::size(kRemedies); ++r) {
    if (!remedy_used[r]) continue;
    remedies += remedies.empty() ? "" : "; ";
    remedies += kRemedies[r];
  }
  return bits + ". What to do: " + remedies;
}

const char* robotModeName(RCI::robot::RobotMode mode) {
  using RCI::robot::RobotMode;
  switch (mode) {
    case RobotMode::kOther: return "kOther";
    case RobotMode::kIdle: return "kIdle";
    case RobotMode::kMove: return "kMove";
    case RobotMode::kGuiding: return "kGuiding";
    case RobotMode::kReflex: return "kReflex";
    case RobotMode::kUserStopped: return "kUserStopped";
    case RobotMode::kAutomaticErrorRecovery: return "kAutomaticErrorRecovery";
  }
  return "unknown";
}

}  // namespace xmate::client
