// SPDX-License-Identifier: Apache-2.0
// The soak's motions: the places they go between (around the arm's home, well inside the joint ranges
// and the workspace), the order they take turns in, and one function per kind that runs it (soak.h).
#pragma once

#include <array>

#include <xmate/move.h>
#include <xmate/robot.h>

#include "soak/soak.h"
#include "teach/executor.h"
#include "teach/program.h"

namespace rci_cli::soak {

using Joints = std::array<double, 7>;

// Built once from the home joints: every motion starts and ends at one of these.
struct Waypoints {
  Joints home{};
  Joints away{};              // MOVEJ goes home -> away -> home
  xmate::cart_pos home_pose;  // the TCP at home (the arm angle kept by every Cartesian move)
  xmate::cart_pos line_end;   // MOVEL: home_pose -> line_end -> home_pose
  xmate::cart_pos arc_via;    // MOVEC: home_pose -> (arc_via) -> arc_end -> (arc_via) -> home_pose
  xmate::cart_pos arc_end;
  Joints q_line_end{}, q_arc_end{};  // the joints at line_end and arc_end (inverse kinematics)
  xmate::teach::Program path;        // one PATH instruction: out and back from home
};

// Throws std::runtime_error if a Cartesian waypoint has no inverse kinematics (not for the models
// the soak runs: the offsets are chosen for the xMate Pro 7's home).
Waypoints waypointsFrom(xmate::XmateType type, const Joints& home);

// The motion that comes at `index` in the soak, and the joints it starts from (where the previous
// one ends; after a failure the soak moves there first).
MotionKind kindAt(long index);
const Joints& startAt(long index, const Waypoints& at);

// Runs the motion at `index` from where the arm is. Throws what the library throws (or a
// std::runtime_error with the executor's report message) when it fails.
void runMotionAt(long index, xmate::Robot& robot, xmate::teach::Executor& executor, const Waypoints& at);

}  // namespace rci_cli::soak
