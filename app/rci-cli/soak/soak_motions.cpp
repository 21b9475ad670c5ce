// SPDX-License-Identifier: Apache-2.0
// The soak's waypoints and motions (soak_motions.h): MOVEJ, MOVEL and MOVEC at speed 1.0 back and
// forth, a PATH replayed by the teach Executor, and two callbacks written as the vendor manual's
// programs are (examples/): each keeps its own clock with time += 0.001 per call.
#include "soak/soak_motions.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <xmate/model.h>

#include "model/robot_spec.h"

namespace rci_cli::soak {
namespace {

using xmate::cart_pos;
using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;

constexpr double kSpeed = 1.0;  // MOVEJ, MOVEL, MOVEC and the PATH's pace

// MOVEJ's far end, from home (rad).
constexpr Joints kAwayOffset{0.4, 0.25, -0.3, 0.35, 0.3, -0.3, 0.5};
// MOVEL's line and MOVEC's half circle (radius 8 cm in the x-z plane, down and back up), from the
// TCP at home (m, base frame).
constexpr std::array<double, 3> kLineOffset{0.08, 0.06, -0.1};
constexpr std::array<double, 3> kArcViaOffset{0.08, 0, -0.08};
constexpr std::array<double, 3> kArcEndOffset{0, 0, -0.16};

// The PATH's demonstration and the joint callback: out and back on a few joints (rad) in a period (s).
constexpr Joints kPathSwing{0.25, 0.2, 0, -0.3, 0, 0.3, 0};
constexpr double kPathPeriod = 2.0;
constexpr double kPathRateHz = 100;
constexpr Joints kJointSwing{0.3, 0, 0.2, 0, -0.3, 0, 0.4};
constexpr double kJointPeriod = 2.5;

// The manual's Cartesian arc (examples/cartesian_motion.cpp) from home, with a shorter period: the
// TCP swings along a circle of kArcRadius in the x-z plane, out to 90 degrees and back. The manual's
// 0.2 m would leave the workspace from home (it starts 10 cm lower); at 0.15 m and 3 s the joints
// stay below 1 rad/s.
constexpr double kArcRadius = 0.15;
constexpr double kArcPeriod = 3.0;

// The order the motions take turns in: each leg's kind and where it starts.
enum class Start { kHome, kAway, kLineEnd, kArcEnd };
struct Leg {
  MotionKind kind;
  Start start;
};
constexpr Leg kLegs[] = {
    {MotionKind::kMoveJ, Start::kHome},  {MotionKind::kMoveJ, Start::kAway},
    {MotionKind::kMoveL, Start::kHome},  {MotionKind::kMoveL, Start::kLineEnd},
    {MotionKind::kMoveC, Start::kHome},  {MotionKind::kMoveC, Start::kArcEnd},
    {MotionKind::kPath, Start::kHome},   {MotionKind::kCartesianCallback, Start::kHome},
    {MotionKind::kJointCallback, Start::kHome},
};
constexpr long kLegCount = long(sizeof kLegs / sizeof kLegs[0]);

const Leg& legAt(long index) { return kLegs[index % kLegCount]; }

cart_pos shifted(const cart_pos& from, const std::array<double, 3>& by) {
  cart_pos to = from;
  to.pos[3] += by[0];
  to.pos[7] += by[1];
  to.pos[11] += by[2];
  return to;
}

// q0 moved by swing * (1 - cos(2 pi t / period)) / 2: at rest at q0 at t = 0 and t = period.
Joints cosineSwing(const Joints& q0, const Joints& swing, double period, double t) {
  Joints q = q0;
  const double s = (1 - std::cos(2 * std::numbers::pi * t / period)) / 2;
  for (size_t j = 0; j < q.size(); ++j) q[j] += swing[j] * s;
  return q;
}

// The joints at `pose` with home's arm angle (what MOVEL and MOVEC keep), nearest to home.
Joints jointsAt(xmate::XmateModel& model, const cart_pos& pose, const Joints& home, double psi) {
  Joints q{};
  const int result = model.GetJointPos(pose.pos, psi, home, q);
  if (result != 0)
    throw std::runtime_error("soak: no inverse kinematics for a waypoint (code " + std::to_string(result) + ")");
  return q;
}

// One PATH instruction: the cosine swing from home, sampled as a demonstration is stored.
xmate::teach::Program pathProgram(xmate::XmateType type, const Joints& home) {
  xmate::teach::Instruction in;
  in.type = xmate::teach::InstructionType::kPath;
  in.name = "swing";
  in.speed = kSpeed;
  in.path.rate_hz = kPathRateHz;
  const int samples = int(std::lround(kPathPeriod * kPathRateHz));
  for (int k = 0; k <= samples; ++k)
    in.path.q.push_back(cosineSwing(home, kPathSwing, kPathPeriod, double(k) / kPathRateHz));
  xmate::teach::Program program;
  program.robot = &xmate::model::robotSpec(type);
  program.instructions.push_back(in);
  return program;
}

void moveJ(xmate::Robot& robot, const Joints& target) {
  if (!xmate::MOVEJ(kSpeed, robot.receiveRobotState().q, target, robot))
    throw std::runtime_error("MOVEJ did not reach its target");
}

void moveL(xmate::Robot& robot, const cart_pos& target_pose) {
  cart_pos start, target = target_pose;
  start.pos = robot.receiveRobotState().toolTobase_pos_m;
  if (!xmate::MOVEL(kSpeed, start, target, robot)) throw std::runtime_error("MOVEL did not reach its target");
}

void moveC(xmate::Robot& robot, const cart_pos& via_pose, const cart_pos& target_pose) {
  cart_pos start, via = via_pose, target = target_pose;
  start.pos = robot.receiveRobotState().toolTobase_pos_m;
  if (!xmate::MOVEC(kSpeed, start, via, target, robot)) throw std::runtime_error("MOVEC did not reach its target");
}

void replayPath(xmate::Robot& robot, xmate::teach::Executor& executor, const xmate::teach::Program& program) {
  const xmate::teach::RunReport report = executor.run(robot, program);
  if (report.outcome != xmate::teach::RunState::kFinished)
    throw std::runtime_error(std::string(xmate::teach::runStateName(report.outcome)) + ": " + report.message);
}

// The manual's Cartesian program: its own clock, the arc relative to the pose at the first call.
void cartesianArc(xmate::Robot& robot) {
  robot.startMove(CM::kCartesianPosition, MM::kCartesianPosition);
  std::array<double, 16> init_position{};
  bool init = true;
  double time = 0;
  robot.Control(xmate::CartesianControl([&](RCI::robot::RobotState robot_state) -> xmate::CartesianPose {
    if (init) {
      init_position = robot_state.toolTobase_pos_m;
      init = false;
    }
    time += 0.001;
    const double angle = std::numbers::pi / 4 * (1 - std::cos(2 * std::numbers::pi / kArcPeriod * time));
    xmate::CartesianPose output{};
    output.toolTobase_pos_c = init_position;
    output.toolTobase_pos_c[3] += kArcRadius * std::sin(angle);
    output.toolTobase_pos_c[11] += kArcRadius * (std::cos(angle) - 1);
    return time >= kArcPeriod - 1e-9 ? xmate::MotionFinished(output) : output;
  }));
}

// The manual's joint program, the plan a cosine swing: its own clock likewise.
void jointCosine(xmate::Robot& robot) {
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  Joints init_position{};
  bool init = true;
  double time = 0;
  robot.Control(xmate::JointControl([&](RCI::robot::RobotState robot_state) -> xmate::JointPositions {
    if (init) {
      init_position = robot_state.q;
      init = false;
    }
    time += 0.001;
    xmate::JointPositions output{};
    output.q = cosineSwing(init_position, kJointSwing, kJointPeriod, std::min(time, kJointPeriod));
    return time >= kJointPeriod - 1e-9 ? xmate::MotionFinished(output) : output;
  }));
}

}  // namespace

Waypoints waypointsFrom(xmate::XmateType type, const Joints& home) {
  xmate::XmateModel model(type);
  model.SetSpeedCheckInterval(0);  // the waypoints are far apart: no speed check between them
  Waypoints at;
  at.home = home;
  at.away = home;
  for (size_t j = 0; j < home.size(); ++j) at.away[j] += kAwayOffset[j];
  at.home_pose.pos = model.GetCartPose(home);
  at.line_end = shifted(at.home_pose, kLineOffset);
  at.arc_via = shifted(at.home_pose, kArcViaOffset);
  at.arc_end = shifted(at.home_pose, kArcEndOffset);
  const double psi = model.GetPsi(home);
  at.q_line_end = jointsAt(model, at.line_end, home, psi);
  at.q_arc_end = jointsAt(model, at.arc_end, home, psi);
  at.path = pathProgram(type, home);
  return at;
}

MotionKind kindAt(long index) { return legAt(index).kind; }

const Joints& startAt(long index, const Waypoints& at) {
  switch (legAt(index).start) {
    case Start::kAway: return at.away;
    case Start::kLineEnd: return at.q_line_end;
    case Start::kArcEnd: return at.q_arc_end;
    case Start::kHome: break;
  }
  return at.home;
}

void runMotionAt(long index, xmate::Robot& robot, xmate::teach::Executor& executor, const Waypoints& at) {
  const Leg& leg = legAt(index);
  const bool back = leg.start != Start::kHome;
  switch (leg.kind) {
    case MotionKind::kMoveJ: return moveJ(robot, back ? at.home : at.away);
    case MotionKind::kMoveL: return moveL(robot, back ? at.home_pose : at.line_end);
    case MotionKind::kMoveC: return moveC(robot, at.arc_via, back ? at.home_pose : at.arc_end);
    case MotionKind::kPath: return replayPath(robot, executor, at.path);
    case MotionKind::kCartesianCallback: return cartesianArc(robot);
    case MotionKind::kJointCallback: return jointCosine(robot);
  }
}

}  // namespace rci_cli::soak
