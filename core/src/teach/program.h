// SPDX-License-Identifier: Apache-2.0
// Programs of the teach feature: an ordered list of instructions -- MOVEJ / MOVEL / MOVEC
// to taught targets, PATH (a demonstrated path replayed as taught), WAIT, SET_DO, WAIT_DI -- for
// one robot model. Plain data; the file format is
// program_io.h's job, running it executor.h's.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <xmate/rci_types.h>
#include <xmate/types.h>

#include "model/robot_spec.h"
#include "model/signal_names.h"
#include "teach/path.h"

namespace xmate::teach {

// A taught position: joint angles, a TCP pose with the arm angle, or both (recording stores both).
struct Target {
  bool has_q = false;
  std::array<double, 7> q{};       // rad; element 6 is 0 on 6-axis models
  bool has_pose = false;
  std::array<double, 16> pose{};   // TCP in the base frame, 4x4 row-major, m
  bool has_psi = false;            // without it a move keeps the arm angle it starts with
  double psi = 0;                  // arm angle, rad (7-axis; ignored on 6-axis models)
};

enum class InstructionType { kMoveJ, kMoveL, kMoveC, kWait, kSetDo, kWaitDi, kPath };

// "MOVEJ", "MOVEL", "MOVEC", "WAIT", "SET_DO", "WAIT_DI", "PATH".
const char* typeName(InstructionType type);
// MOVEJ, MOVEL, MOVEC and PATH.
bool isMotion(InstructionType type);

struct Instruction {
  InstructionType type = InstructionType::kMoveJ;
  std::string name;        // optional label ("P1")
  Target target;           // MOVEJ / MOVEL / MOVEC
  Target via;              // MOVEC only: the arc passes through it
  JointPath path;          // PATH only: the demonstrated joints at a fixed rate (teach/path.h)
  double speed = 0.3;      // motions: speed ratio in (0, 1]; PATH: of the demonstrated pace
  int ms = 0;              // WAIT: milliseconds
  int signal = 0;          // SET_DO: DOSIGNAL index; WAIT_DI: DISIGNAL index (0..5)
  bool value = false;      // SET_DO level / WAIT_DI expected level
  int timeout_ms = 0;      // WAIT_DI: give up after this long (> 0)
};

// The payload the controller was told about (Robot::setLoad): mass, centre of mass in the flange
// frame, inertia about it (row-major 3x3).
struct Payload {
  double mass = 0;                   // kg
  std::array<double, 3> center{};    // m
  std::array<double, 9> inertia{};   // kg m^2
};

struct Program {
  // The model it was taught for (static storage: model::robotSpec / findRobotSpec); never null.
  const model::RobotSpec* robot = &model::robotSpec(XMATE7_PRO);
  // The tool (TCP in the flange frame, 4x4 row-major) and payload the program was taught with. Its
  // poses are poses of that TCP: with another tool on the robot MOVEL/MOVEC would drive the new TCP
  // to them, so a run refuses when the robot's TCP does not match (toolMismatch, preflight.h).
  // Programs saved before RCI Studio recorded the tool have has_tool = false.
  bool has_tool = false;
  std::array<double, 16> tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  Payload load;
  std::vector<Instruction> instructions;
};

// The digital signals a program names: model/signal_names.h.
using model::diIndex;
using model::diName;
using model::doIndex;
using model::doName;
using model::kKukaSignalCount;
using model::kXmateSignalCount;
using model::knownSignals;

// "instruction 3 (MOVEL \"P3\")": how messages name an instruction (1-based).
std::string describe(const Program& program, size_t index);

}  // namespace xmate::teach
