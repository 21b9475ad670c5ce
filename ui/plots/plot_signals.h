// SPDX-License-Identifier: Apache-2.0
// The signals the live plots record -- per joint (positions, torques, currents) or per component (the
// F/T sensor's wrench, the RSI late-answer count): names, units and which chart (quantity) shows them.
#pragma once

#include <QString>

namespace rci::ui::plots {

// Joints (or a signal's components) per signal: the buffer keeps this many columns of each.
inline constexpr int kJointCount = 7;

// Order is the column order of the buffer and of a whole-buffer CSV export. The first six are the
// xMate's (recorded from its state samples), the rest an arm's over arm samples (a KUKA over RSI).
enum class Signal : int {
  kPositionMeasured = 0,
  kPositionCommanded,
  kVelocityMeasured,
  kTorqueMeasured,
  kTorqueCommanded,
  kTorqueExternal,
  kAxisActual,       // ArmSample::q, rad
  kAxisSetPoint,     // ArmSample::q_command, rad
  kAxisVelocity,     // difference of consecutive actual positions over their time, rad/s
  kGearTorque,       // ArmSample::gear_torque, Nm (Capability::kGearTorques)
  kMotorCurrent,     // ArmSample::motor_current, A (Capability::kMotorCurrents)
  kSensorForce,      // the F/T sensor's Fx Fy Fz, N, sensor frame (components 0..2)
  kSensorTorque,     // the F/T sensor's Tx Ty Tz, Nm, sensor frame (components 0..2)
  kLateAnswers,      // the robot's count of late answers (RSI Delay), one component
  kTcpActual,        // ArmSample::tcp_position: X Y Z of the TCP (or flange), m, base frame (components 0..2)
  kTcpSetPoint,      // ArmSample::tcp_position_command (Capability::kTcpSetPoint), m
};
inline constexpr int kSignalCount = 16;
inline constexpr int kChannelCount = kSignalCount * kJointCount;

// The charts. The first kQuantityCount are the joint charts every arm may have; the others are
// shown only when the arm offers their signals (and, see quantityCollapses, one of them is ticked).
enum class Quantity : int { kPosition = 0, kVelocity, kTorque, kMotorCurrent, kForce, kDelay, kTcp };
inline constexpr int kQuantityCount = 3;
inline constexpr int kAllQuantityCount = 7;

// Every function here: any thread, real-time safe except those returning a QString (they allocate).
Quantity quantityOf(Signal signal);
QString quantityTitle(Quantity quantity);  // "Joint position", "Motor current", "Force sensor", "TCP position", ...
QString quantityUnit(Quantity quantity);   // "rad", "rad/s", "Nm", "A", "N, Nm", "count", "m"
// An extra chart (motor current, force sensor, late answers) takes room only while one of its
// signals is ticked; the joint charts stay.
bool quantityCollapses(Quantity quantity);
QString signalLabel(Signal signal);        // "measured", "commanded", "external", "actual", "set-point", ...
QString signalKey(Signal signal);          // "q", "q_c", "dq", "tau", "tau_c", "tau_ext", "q_set", ... (CSV)
QString signalUnit(Signal signal);         // the unit of the signal's values ("" for a count)
// Per joint (the joint chooser applies) or per component of something else (sensor, link).
bool isJointSignal(Signal signal);
// How many columns the signal has: kJointCount per joint, 3 for a sensor's force or torque and for the
// TCP position, 1 for a count.
int componentCount(Signal signal);
// A non-joint signal's component: "Fx", "Ty", "X", "" for a single value.
QString componentName(Signal signal, int component);

// A series' id (also its buffer channel): signal * kJointCount + joint (or component).
inline int channelOf(Signal signal, int joint) { return static_cast<int>(signal) * kJointCount + joint; }
inline Signal signalOfChannel(int channel) { return static_cast<Signal>(channel / kJointCount); }
inline int jointOfChannel(int channel) { return channel % kJointCount; }

}  // namespace rci::ui::plots
