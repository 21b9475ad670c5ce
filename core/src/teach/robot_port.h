// SPDX-License-Identifier: Apache-2.0
// The executor's one backend: what it needs from a robot -- the model, the newest joints and TCP,
// the tool, digital IO, the joints a motion can reach, and the motions themselves (MOVEJ / MOVEL /
// MOVEC, a PATH's timing) streamed through the robot's real-time loop. Implemented once per robot
// family (rci_port.h: an xMate through the vendor API; rsi_port.h: a KUKA over RSI); arm_port.h
// picks the one for an arm::Arm. The executor itself never names a family.
#pragma once

#include <array>

#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "teach/path_timing.h"
#include "teach/program.h"

namespace xmate::teach {

class PathRecording;
class TimeScaling;
struct InstructionReport;

// The executor's side of a motion, asked by the port on the real-time thread every cycle: whether
// to pause or stop, the speed override, and the motion's progress. Real-time safe (atomics only).
class MotionControl {
 public:
  virtual ~MotionControl() = default;
  // The speed override when the motion starts (0.1 .. 1).
  virtual double speedOverride() const = 0;
  // What the motion's time scaling should go to this cycle: 0 to pause or stop, else the override.
  virtual double scalingTarget(const TimeScaling& scaling) = 0;
  // A stop was requested and the time scaling has come to rest: the motion ends where it stands.
  virtual bool stoppedHere(const TimeScaling& scaling) const = 0;
  // The motion's progress, 0..1.
  virtual void storeFraction(double fraction) = 0;
};

class RobotPort {
 public:
  struct Reading {
    std::array<double, 7> q{};      // rad (element 6 is 0 on 6-axis models)
    std::array<double, 16> tcp{};   // measured TCP in the base frame, row-major, m
    double psi = 0;                 // arm angle (7-axis), rad
  };
  virtual ~RobotPort() = default;

  // ---- The executor's thread (not real-time) -----------------------------------------------------
  virtual const model::RobotSpec& spec() const = 0;
  virtual Reading read() = 0;
  virtual std::array<double, 16> toolFrame() = 0;  // the robot's TCP in the flange frame
  // Throw std::exception (its message says what to do) where the robot cannot.
  virtual void setDO(int signal, bool value) = 0;
  virtual bool getDI(int signal) = 0;
  // The joints (rad) this session can reach at all, when the robot limits them beyond its axis
  // ranges (a KUKA over RSI: the pose at RSI_ON plus the context's correction limits); false when it
  // does not (an xMate) or does not know yet.
  virtual bool reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) {
    (void)lower;
    (void)upper;
    return false;
  }

  // ---- Motions: the executor's thread, blocking; their cycles run on the robot's real-time thread ----
  // MOVEJ, MOVEL or MOVEC `in` of `program` from where the arm is, planned with `model` (the
  // program's tool, the soft limits), at in.speed scaled by `control` each cycle. Fills the report's
  // motion fields (duration, tracking errors, settling; status kStopped when a stop ended it).
  // Throws MotionException (what to change) when it cannot start, ControlException when the
  // controller ends it.
  virtual void move(const Program& program, const Instruction& in, const model::ArmKinematics& model,
                    MotionControl& control, InstructionReport& report) = 0;
  // Before anything moves: throws MotionException naming the path time when this robot cannot
  // follow `timing` (a PATH recorded at `rate_hz`). Nothing to check by default.
  virtual void checkPath(const PathTiming& timing, double rate_hz) {
    (void)timing;
    (void)rate_hz;
  }
  // A PATH's timing from its first sample (the arm is there: the lead-in brought it), each cycle's
  // measured joints into `recording`; fills the report as move() does.
  virtual void streamPath(const JointPath& path, const PathTiming& timing, const model::ArmKinematics& model,
                          MotionControl& control, PathRecording& recording, InstructionReport& report) = 0;
};

}  // namespace xmate::teach
