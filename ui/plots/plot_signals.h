// SPDX-License-Identifier: Apache-2.0
// The signals the live plots record per joint: names, units and which chart (quantity) shows them.
#pragma once

#include <QString>

namespace rci::ui::plots {

inline constexpr int kJointCount = 7;

// Order is the column order of the buffer and of a whole-buffer CSV export.
enum class Signal : int {
  kPositionMeasured = 0,
  kPositionCommanded,
  kVelocityMeasured,
  kTorqueMeasured,
  kTorqueCommanded,
  kTorqueExternal,
};
inline constexpr int kSignalCount = 6;
inline constexpr int kChannelCount = kSignalCount * kJointCount;

// The three charts.
enum class Quantity : int { kPosition = 0, kVelocity, kTorque };
inline constexpr int kQuantityCount = 3;

Quantity quantityOf(Signal signal);
QString quantityTitle(Quantity quantity);  // "Joint position"
QString quantityUnit(Quantity quantity);   // "rad", "rad/s", "Nm"
QString signalLabel(Signal signal);        // "measured", "commanded", "external"
QString signalKey(Signal signal);          // "q", "q_c", "dq", "tau", "tau_c", "tau_ext" (CSV)
// A series' id (also its buffer channel): signal * kJointCount + joint.
inline int channelOf(Signal signal, int joint) { return static_cast<int>(signal) * kJointCount + joint; }
inline Signal signalOfChannel(int channel) { return static_cast<Signal>(channel / kJointCount); }
inline int jointOfChannel(int channel) { return channel % kJointCount; }

}  // namespace rci::ui::plots
