// SPDX-License-Identifier: Apache-2.0
// The executor's port to an xMate (rci_port.h): MOVEJ streams the joint S-curve in joint position
// mode, a PATH its re-timed joints the same way (executor_path.cpp prepares it), MOVEL/MOVEC stream the
// timed Cartesian path in Cartesian position mode. All sample their plan at a plan time that
// advances by k * dt per cycle (TimeScaling), which is how pause, stop and the speed override act
// smoothly on the path. After a stall of the client's loop the command continues
// what the controller extrapolated and rejoins the plan (client/stall_bridge.h). The callbacks run
// on the real-time thread: they touch only atomics (relaxed loads/stores) and locals, and allocate
// nothing.
#include <algorithm>
#include <cmath>

#include <xmate/exception.h>
#include <xmate/joint_motion.h>

#include "client/clocked_control.h"
#include "client/connection.h"
#include "client/limit_check.h"
#include "client/move_check.h"
#include "client/stall_bridge.h"
#include "model/robot_spec.h"
#include "planning/cartesian_pose.h"
#include "planning/cartesian_trajectory.h"
#include "teach/executor.h"
#include "teach/executor_path.h"
#include "teach/rci_port.h"
#include "teach/path_timing.h"
#include "teach/preflight.h"
#include "teach/targets.h"
#include "teach/plan_scaling.h"
#include "teach/settle.h"
#include "teach/time_scaling.h"

namespace xmate::teach {
namespace {

using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using RCI::robot::RobotState;

constexpr double kDt = 1e-3;
// After a motion the arm is at rest when every measured joint is this close to the last command
// and this slow: far below what an operator or a next instruction notices (0.003 deg), well above
// what a real arm's encoders and friction leave at standstill.
constexpr double kSettleSpeed = 2e-3;      // rad/s: "at rest" on the xMate also means this slow

// Plan time driven by the controller's message_id and the time scaling. As client/move.cpp's
// MotionClock it starts at the first state reporting robot_mode kMove (earlier states were sent
// before the controller started the motion); the first two commands are the plan's start, then each
// elapsed cycle -- also those a client stall left unanswered -- advances the plan by k * dt.
struct ScaledClock {
  TimeScaling scaling;
  int calls = 0;  // states of the motion seen (robot_mode kMove)
  uint64_t first_id = 0, last_id = 0;
  double plan_time = 0;

  ScaledClock(double k, double rate) : scaling(k, rate) {}
  double advance(const RobotState& s, double target_k) {
    scaling.setTarget(target_k);
    if (calls == 0 && s.robot_mode != RCI::robot::RobotMode::kMove) return 0;
    if (calls++ == 0) first_id = s.message_id;
    if (calls <= 2) {
      last_id = s.message_id;
      return 0;
    }
    uint64_t cycles = s.message_id > last_id ? s.message_id - last_id : 0;
    last_id = s.message_id;
    if (cycles > 1000) cycles = 1000;  // a gap that long ends the motion in the controller anyway
    for (uint64_t c = 0; c < cycles; ++c) {
      scaling.step(kDt);
      plan_time += scaling.value() * kDt;
    }
    return plan_time;
  }
  double elapsed() const { return double(last_id - first_id) * kDt; }
  // The plan time k cycles before the current one, at the current rate (for the stall bridge).
  double planTimeBefore(int k) const { return std::max(0.0, plan_time - k * scaling.value() * kDt); }
};

double jointError(const RobotState& s, int dof) {
  double m = 0;
  for (int i = 0; i < dof; ++i) m = std::max(m, std::abs(s.q_c[i] - s.q[i]));
  return m;
}

double tcpError(const RobotState& s) {
  const auto& c = s.toolTobase_pos_c;
  const auto& m = s.toolTobase_pos_m;
  return std::sqrt(std::pow(c[3] - m[3], 2) + std::pow(c[7] - m[7], 2) + std::pow(c[11] - m[11], 2));
}

// The limits the robot was given through this client (the soft limits and safety box sent with
// setJointLimit / setCartesianLimit, client/limit_check.h), from where the arm is -- checked also when
// the caller's pre-flight did not know them.
client::LimitWatch robotLimits(Robot& robot, const model::ArmKinematics& model, const std::array<double, 7>& q_start) {
  return client::LimitWatch(model.spec(), robot.connection().remembered().limits, q_start, &model);
}

void requireWithinLimits(const std::string& problem) {
  if (!problem.empty()) throw MotionException(problem + "; re-teach it within the limits, or change the limits");
}

bool atRest(const RobotState& s, int dof) {
  if (jointError(s, dof) >= kSettleTolerance) return false;
  for (int i = 0; i < dof; ++i)
    if (std::abs(s.dq_m[i]) >= kSettleSpeed) return false;
  return true;
}

// Waits until the arm is at rest at the last command (settle.h).
void settleAtTarget(Robot& robot, int dof, InstructionReport& report) {
  settle(
      [&] {
        const RobotState s = robot.receiveRobotState();
        return SettleReading{atRest(s, dof), jointError(s, dof), s.message_id};
      },
      kDt, report);
}

// Ends a motion that was started but will not be streamed (its plan failed or is empty).
void endStartedMotion(Robot& robot) {
  try {
    robot.stopMove();
  } catch (const std::exception&) {
    // The controller ended it already (an error, a lost session): nothing left to stop.
  }
}

// MOVEJ's plan for streamJointPlan: the synchronised S-curve from where the arm is to the goal,
// planned again from where it really is at the motion's first state.
struct JointGoalPlan {
  JointMotionGenerator& generator;
  std::array<double, 7> q0, goal;
  int dof;

  double total() const { return generator.GetTime(); }
  void startFrom(const std::array<double, 7>& q) {
    q0 = q;
    generator.calculateSynchronizedValues_joint(q0);
  }
  client::StallBridge::Vec at(double time) {
    std::array<double, 7> delta{}, plan{};
    const bool finished = generator.calculateDesiredValues_joint(time, delta);
    for (int i = 0; i < dof; ++i) plan[i] = finished ? goal[i] : q0[i] + delta[i];
    return plan;
  }
  bool finished(double time) const { return time >= generator.GetTime(); }
};

// A PATH's plan for streamJointPlan: its timing (path_timing.h), which starts at the path's first
// sample wherever the arm is (the lead-in brought it there; the stall bridge takes out what is left).
struct TimingPlan {
  const PathTiming& timing;

  double total() const { return timing.duration; }
  void startFrom(const std::array<double, 7>&) {}
  client::StallBridge::Vec at(double time) const { return timingAt(timing, time); }
  bool finished(double time) const { return time >= timing.duration; }
};

// The largest joint and TCP tracking errors of a motion, from its states. Real-time safe.
struct Tracking {
  int dof;
  double joint = 0, tcp = 0;
  void add(const RobotState& s) {
    joint = std::max(joint, jointError(s, dof));
    tcp = std::max(tcp, tcpError(s));
  }
};

// After a motion streamed for `seconds` of controller time: the report's motion fields, then the
// wait until the arm is at rest.
void finishMotion(Robot& robot, int dof, double seconds, const Tracking& tracking, bool stopped,
                  InstructionReport& report) {
  report.duration = seconds;
  report.max_joint_error = tracking.joint;
  report.max_tcp_error = tracking.tcp;
  if (stopped) {
    report.status = InstructionStatus::kStopped;
    report.message = "stopped by the operator";
  }
  settleAtTarget(robot, dof, report);
}

// MOVEJ's and PATH's streaming: the plan in joint position mode at the scaled plan time; returns
// true when a stop ended it on the way.
template <class Plan, class OnState>
bool streamJointPlan(Robot& robot, const model::RobotSpec& spec, MotionControl& control, Plan& plan, ScaledClock& clock,
                     double share, OnState on_state) {
  const int dof = spec.dof;
  const client::StallBridge::Limits limits = client::jointBridgeLimits(spec, share);
  client::StallBridge bridge(dof, limits);
  client::StallBridge::Vec last = plan.at(0);
  bool stopped = false;
  auto planAt = [&](double time) { return plan.at(time); };
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  client::controlByMessageId(robot, JointControl([&](RobotState s) -> JointPositions {
    const bool starting = clock.calls == 0;
    limitScalingAtPlan(clock.scaling, clock.plan_time, planAt, limits, dof, 1.0);
    const double t = clock.advance(s, control.scalingTarget(clock.scaling));
    if (starting && clock.calls == 1) {
      plan.startFrom(s.q);  // where the motion really starts
      last = s.q;
      bridge.startAt(s.message_id, s.q_c);  // the "hold still" command the controller has now
    }
    on_state(s, t);
    control.storeFraction(std::min(1.0, t / plan.total()));
    JointPositions out;
    if (control.stoppedHere(clock.scaling) && !bridge.bridging()) {
      stopped = true;
      out.q = last;
      out.motion_finished = true;
      return out;
    }
    bool plan_finished = false;
    const client::StallBridge::Vec q = bridge.command(s.message_id, [&](int k) {
      const double time = clock.planTimeBefore(k);
      if (k == 0) plan_finished = plan.finished(time);
      return plan.at(time);
    });
    out.q = q;
    last = out.q;
    out.motion_finished = plan_finished && !bridge.bridging();
    return out;
  }));
  return stopped;
}

}  // namespace

RciPort::RciPort(Robot& robot) : robot_(robot), spec_(model::robotSpec(robot.type())) {}

RobotPort::Reading RciPort::read() {
  const RobotState s = robot_.receiveRobotState();
  return {s.q, s.toolTobase_pos_m, s.psi_m};
}

std::array<double, 16> RciPort::toolFrame() { return robot_.toolFrame(); }

void RciPort::setDO(int signal, bool value) { robot_.setDO(RCI::robot::DOSIGNAL(uint8_t(signal)), value); }

bool RciPort::getDI(int signal) { return robot_.getDI(RCI::robot::DISIGNAL(uint8_t(signal))); }

void RciPort::move(const Program& program, const Instruction& in, const model::ArmKinematics& model,
                   MotionControl& control, InstructionReport& report) {
  const model::RobotSpec& spec = spec_;
  const int dof = spec.dof;
  const RobotState state = robot_.receiveRobotState();
  // The tool may have been changed since the pre-flight (another client, the pendant).
  if (usesTool(in)) {
    const ToolMismatch mismatch = toolMismatch(program, state.q, state.toolTobase_pos_m);
    if (!toolMatches(mismatch)) throw MotionException(toolMismatchText(mismatch, program));
  }

  const double share = in.speed * kSpeedShare;
  ScaledClock clock(control.speedOverride(), safeScalingRate(share, accelOverVelocity(in.type == InstructionType::kMoveJ, spec)));
  bool stopped = false;
  Tracking tracking{dof};
  auto track = [&](const RobotState& s) { tracking.add(s); };

  if (in.type == InstructionType::kMoveJ) {
    std::array<double, 7> goal{};
    const int rc = jointGoal(in.target, model, state.q, goal);
    if (rc != XmateModel::kIkOk)
      throw MotionException(std::string("the target pose cannot be reached: ") + client::ikFailureText(rc) +
                            " (IK code " + std::to_string(rc) + ")");
    client::LimitWatch watch = robotLimits(robot_, model, state.q);
    requireWithinLimits(client::checkJointLine(watch, state.q, goal, dof));
    JointMotionGenerator generator(share, goal, robot_.type());
    JointGoalPlan plan{generator, state.q, goal, dof};
    plan.startFrom(state.q);
    if (plan.total() > 0)
      stopped = streamJointPlan(robot_, spec, control, plan, clock, share,
                                [&](const RobotState& s, double) { track(s); });
  } else {
    // Planned once the controller accepted the motion, from where the arm is then: the previous
    // motion's stop may have taken it a little further while startMove was retried. Until Control()
    // the client answers every state with "hold still".
    robot_.startMove(CM::kCartesianPosition, MM::kCartesianPosition);
    planning::CartesianPath path;
    planning::CartesianTrajectory trajectory;
    try {
      const std::array<double, 7> q_now = robot_.receiveRobotState().q;
      path = cartesianPath(in, model, q_now);
      client::JointSamples joints;
      trajectory = client::planWithinJointLimits(typeName(in.type), path, share, model, q_now, &joints);
      client::LimitWatch watch = robotLimits(robot_, model, q_now);
      requireWithinLimits(client::checkJointPath(watch, joints));
    } catch (...) {
      endStartedMotion(robot_);
      throw;
    }
    const double total = planning::duration(trajectory);
    if (!(total > 0)) endStartedMotion(robot_);
    if (total > 0) {
      CartesianPose last;
      last.toolTobase_pos_c = planning::poseToRowMajor(path.start.pose);
      last.psi_valid = dof == 7;
      last.psi_c = path.start.psi;
      const Eigen::Matrix3d reference = path.start.pose.linear();
      const client::StallBridge::Limits limits = client::cartesianBridgeLimits(share);
      client::StallBridge bridge(7, limits);
      auto planAt = [&](double time) {
        const planning::CartesianSample sample = planning::sampleTrajectory(trajectory, time);
        return client::cartesianCoordinates(sample.pose, sample.psi, reference);
      };
      client::controlByMessageId(robot_, CartesianControl([&](RobotState s) -> CartesianPose {
        track(s);
        const bool starting = clock.calls == 0;
        limitScalingAtPlan(clock.scaling, clock.plan_time, planAt, limits, 7, kCartesianBrakingShare);
        const double t = clock.advance(s, control.scalingTarget(clock.scaling));
        if (starting && clock.calls == 1)
          bridge.startAt(s.message_id, client::cartesianCoordinates(s.toolTobase_pos_c, s.psi_c, reference));
        control.storeFraction(std::min(1.0, t / total));
        if (control.stoppedHere(clock.scaling) && !bridge.bridging()) {
          stopped = true;
          return MotionFinished(last);
        }
        bool plan_finished = false;
        const client::StallBridge::Vec c = bridge.command(s.message_id, [&](int k) {
          const planning::CartesianSample sample = planning::sampleTrajectory(trajectory, clock.planTimeBefore(k));
          if (k == 0) plan_finished = sample.finished;
          return client::cartesianCoordinates(sample.pose, sample.psi, reference);
        });
        last.toolTobase_pos_c = planning::poseToRowMajor(client::poseFromCoordinates(c, reference));
        last.psi_valid = dof == 7;
        last.psi_c = c[6];
        last.motion_finished = plan_finished && !bridge.bridging();
        return last;
      }));
    }
  }
  finishMotion(robot_, dof, clock.elapsed(), tracking, stopped, report);
}

void RciPort::streamPath(const JointPath& path, const PathTiming& timing, const model::ArmKinematics& model,
                         MotionControl& control, PathRecording& recording, InstructionReport& report) {
  client::LimitWatch watch = robotLimits(robot_, model, robot_.receiveRobotState().q);
  requireWithinLimits(client::checkJointPath(watch, path.q));
  ScaledClock clock(control.speedOverride(), safeScalingRate(kPathLimitShare, accelOverVelocity(true, spec_)));
  Tracking tracking{spec_.dof};
  TimingPlan plan{timing};
  const bool stopped = streamJointPlan(robot_, spec_, control, plan, clock, kPathLimitShare,
                                       [&](const RobotState& s, double plan_time) {
                                         tracking.add(s);
                                         recording.add(plan_time, s.q);
                                       });
  finishMotion(robot_, spec_.dof, clock.elapsed(), tracking, stopped, report);
}

}  // namespace xmate::teach
