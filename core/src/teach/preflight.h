// SPDX-License-Identifier: Apache-2.0
// Pre-flight of a program, before anything moves: follows the program from a start
// configuration, resolving every target as the executor will, and reports EVERY problem by
// instruction -- invalid fields, IK reachability, hard and soft joint limits, the Cartesian safety
// box (targets and sampled paths), degenerate arcs, paths too close to singular poses. The same
// trace gives the GUI its preview: the TCP polyline of each motion.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "teach/program.h"

namespace xmate::teach {

inline constexpr std::array<double, 16> kIdentityPose{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// The box the controller keeps the TCP in (Robot::setCartesianLimit): centred on `frame`'s origin,
// edges of `size` along its axes, base frame.
struct SafetyBox {
  std::array<double, 3> size{};                  // m
  std::array<double, 16> frame = kIdentityPose;  // row-major
};

struct TraceOptions {
  std::array<double, 7> q_start{};             // where the robot is when the program starts, rad
  std::array<double, 16> tool = kIdentityPose;  // TCP in the flange frame (Robot::toolFrame())
  bool has_soft_limits = false;                 // Robot::setJointLimit's limits, in rad
  std::array<double, 7> soft_lower{}, soft_upper{};
  bool has_box = false;
  SafetyBox box;
  // The controller's measured TCP at q_start (RobotState::toolTobase_pos_m), for the tool check of a
  // program that records its tool.
  bool has_tcp = false;
  std::array<double, 16> tcp = kIdentityPose;
  // The joints the session can reach (on a KUKA over RSI: the start pose plus the context's
  // correction limits, arm::JointStream::reachableBounds), rad. PATH samples are checked against
  // them.
  bool has_joint_bounds = false;
  std::array<double, 7> joint_lower{}, joint_upper{};
};

struct Problem {
  size_t instruction = 0;  // 0-based index
  std::string message;     // starts with "instruction N (TYPE)"
};

struct InstructionTrace {
  bool traced = false;                          // a motion that could be followed to its end
  std::vector<std::array<double, 3>> tcp_path;  // sampled TCP positions along the motion, m
  std::array<double, 7> q_end{};                // joints after this instruction (rad)
};

struct ProgramTrace {
  std::vector<InstructionTrace> instructions;  // one per instruction (non-motions: traced = false)
  std::vector<Problem> problems;               // in instruction order
  // Not problems, but what the operator should know before the run: a PATH that starts away from
  // where the arm will be first moves to its first sample with a joint move.
  std::vector<Problem> notices;
};

// A PATH starting farther than this (any joint, rad) from where the arm is gets a lead-in: a joint
// move (as MOVEJ, at the PATH's speed) to its first sample.
inline constexpr double kPathLeadIn = 1e-4;

// Never throws for a bad program: every problem becomes a Problem. After a motion that cannot be
// resolved the trace goes on from the last good configuration, so later problems still show.
ProgramTrace traceProgram(const Program& program, const TraceOptions& options);

// traceProgram(...).problems.
std::vector<Problem> preflight(const Program& program, const TraceOptions& options);

// For the 3D view: one polyline of TCP positions (m, base frame) per instruction, sampled along each
// motion from q_start with the given tool; empty for non-motions and for motions that cannot be
// followed (their problems are in traceProgram()).
std::vector<std::vector<std::array<double, 3>>> plannedPath(const Program& program,
                                                            const std::array<double, 7>& q_start,
                                                            const std::array<double, 16>& tool = kIdentityPose);

// How far the robot's TCP is from where the program's tool puts it: the TCP of the program's tool
// at joints q (forward kinematics) against the controller's measured TCP there. Zero for a program
// without a recorded tool.
struct ToolMismatch {
  double distance = 0;  // m
  double angle = 0;     // rad
};
ToolMismatch toolMismatch(const Program& program, const std::array<double, 7>& q, const std::array<double, 16>& tcp);
// Beyond these a run refuses the instructions that use poses (MOVEL, MOVEC, MOVEJ to a pose).
inline constexpr double kToolMismatchDistance = 1e-3;    // m
inline constexpr double kToolMismatchAngle = 0.5 / 57.29577951308232;  // rad (0.5 deg)
bool toolMatches(const ToolMismatch& m);
// "the robot's tool point is 120.0 mm and 0.0 deg away from the one this program was taught with
// (x, y, z = ...)": the problem text, with the program's tool (as the Tool & payload panel takes
// it: metres, then degrees applied as Rz Ry Rx) and what to do.
std::string toolMismatchText(const ToolMismatch& m, const Program& program);
// Whether the instruction's motion depends on the tool: MOVEL, MOVEC, and MOVEJ to a target taught
// as a pose only.
bool usesTool(const Instruction& in);

// All problems as one text, a line each.
std::string problemsText(const std::vector<Problem>& problems);

}  // namespace xmate::teach
