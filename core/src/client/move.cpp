// SPDX-License-Identifier: Apache-2.0
// MOVEJ, MOVEL and MOVEC (docs/client.md, "MOVEJ, MOVEL, MOVEC"): plan with the jerk-limited
// planners of core/src/planning, check the plan (move_check.h), then stream it through
// Robot::Control. MOVEJ runs in joint position mode; MOVEL/MOVEC run in Cartesian position mode, or
// with an XmateModel in joint position mode with IK every cycle. Time in the callbacks comes from
// the controller's message_id, so a lost state does not shift the plan against the controller's
// clock, and after a stall of the client's loop the command continues what the controller
// extrapolated, then rejoins the plan (stall_bridge.h).
#include <xmate/move.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <xmate/joint_motion.h>

#include "client/clocked_control.h"
#include "client/connection.h"
#include "client/limit_check.h"
#include "client/move_check.h"
#include "client/stall_bridge.h"
#include "model/robot_spec.h"
#include "model/xmate_model_access.h"
#include "planning/cartesian_path.h"
#include "planning/cartesian_pose.h"
#include "planning/cartesian_trajectory.h"

namespace xmate {
namespace {

using CM = RCI::robot::StartMoveRequest::ControllerMode;
using MM = RCI::robot::StartMoveRequest::MotionGeneratorMode;
using RCI::robot::RobotState;

constexpr double kDt = 1e-3;

// Seconds since the motion started, counted by the controller's message_id, so a stall of the
// client (states it never answered) does not shift the plan against the controller's clock. The
// clock starts at the first state reporting robot_mode kMove: states sent before the controller
// executed StartMove may reach the callback late (docs/reliability.md), and counting from them
// would start the plan a few ms into the trajectory. The first two commands are the plan's start
// itself (t = 0), so its first step always follows a command at rest.
struct MotionClock {
  bool started = false;
  uint64_t origin = 0;  // message_id of the second state of the motion
  double at(const RobotState& s) {
    if (!started && s.robot_mode != RCI::robot::RobotMode::kMove) return 0.0;
    if (!started) {
      started = true;
      origin = s.message_id + 1;
    }
    return s.message_id <= origin ? 0.0 : double(s.message_id - origin) * kDt;
  }
};

void requireFinite(const char* call, const char* what, const std::array<double, 7>& q, int dof) {
  for (int i = 0; i < dof; ++i)
    if (!std::isfinite(q[i]))
      throw std::invalid_argument(std::string(call) + ": " + what + "[" + std::to_string(i) + "] is not a finite number");
}

void requireWithinJointRange(const char* call, const std::array<double, 7>& q, const model::RobotSpec& spec) {
  for (int i = 0; i < spec.dof; ++i)
    if (q[i] < spec.q_min[i] || q[i] > spec.q_max[i])
      throw MotionException(std::string(call) + ": q_target[" + std::to_string(i) + "] = " + std::to_string(q[i]) +
                            " rad is outside the joint range [" + std::to_string(spec.q_min[i]) + ", " +
                            std::to_string(spec.q_max[i]) + "] of the " + std::string(spec.display_name) +
                            "; choose a reachable target");
}

// Refuses a motion that leaves the joint range, the soft limits or the safety box (limit_check.h).
void requireWithinLimits(const char* call, const std::string& problem) {
  if (!problem.empty())
    throw MotionException(std::string(call) + ": " + problem +
                          "; choose a target (and for MOVEL/MOVEC a path) within the limits, or change the limits");
}

// A kinematic model with the robot's tool: the caller's (copied, so its settings stay untouched) or
// an offline one. Joint speeds are checked over the whole path, not by IK per step.
XmateModel pathModel(Robot& robot, const XmateModel* user_model) {
  XmateModel model = user_model ? *user_model : XmateModel(robot.type());
  if (!user_model) model.SetCoor(robot.toolFrame());
  model.SetSpeedCheckInterval(0);
  return model;
}

// The model's TCP must be the robot's: else IK would drive the wrong point along the path.
void requireModelMatchesRobot(const char* call, XmateModel& model, const RobotState& state) {
  const std::array<double, 16> fk = model.GetCartPose(state.q);
  const double dx = fk[3] - state.toolTobase_pos_m[3], dy = fk[7] - state.toolTobase_pos_m[7],
               dz = fk[11] - state.toolTobase_pos_m[11];
  const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (d > client::kStartPositionTolerance)
    throw MotionException(std::string(call) + ": the model puts the TCP " + std::to_string(d * 1000) +
                          " mm from where the robot reports it; give the model the robot's tool: "
                          "model.SetCoor(robot.toolFrame())");
}

// The path from where the robot is (its held command) to target, through via for an arc.
planning::CartesianPath makePath(const std::array<double, 16>& start_pose, double start_psi, const cart_pos* via,
                                 const cart_pos& target) {
  const planning::PathPoint start = planning::pathPoint(start_pose, start_psi, "the robot's TCP pose");
  const double target_psi = target.psi_valid ? target.psi : start_psi;
  const planning::PathPoint end = planning::pathPoint(target.pos, target_psi, "target");
  if (!via) return planning::makeLinePath(start, end);
  return planning::makeArcPath(start, planning::pathPoint(via->pos, start_psi, "mid"), end);
}

bool moveCartesian(const char* call, double speed_ratio, cart_pos& start, const cart_pos* via, cart_pos& target,
                   Robot& robot, XmateModel* user_model) {
  client::requireSpeedRatio(call, speed_ratio);
  const model::RobotSpec& spec = model::robotSpec(robot.type());
  robot.connection().ensureOpen();
  const client::StandstillWait moved = robot.connection().awaitStandstill(call);  // after a stop: plan from rest
  const RobotState state = robot.receiveRobotState();
  XmateModel model = pathModel(robot, user_model);
  if (user_model) requireModelMatchesRobot(call, model, state);
  client::requireStartPose(call, start.pos, state.toolTobase_pos_m, moved);

  // Start exactly where the robot is (the controller measures the first command against it).
  const std::array<double, 7> q0 = state.q;
  const double psi0 = spec.dof == 7 ? model.GetPsi(q0) : 0.0;
  if (spec.dof == 7 && start.psi_valid && std::abs(std::remainder(start.psi - psi0, 2 * std::numbers::pi)) > client::kStartJointTolerance)
    throw MotionException(std::string(call) + ": start.psi = " + std::to_string(start.psi) +
                          " rad differs from the robot's arm angle " + std::to_string(psi0) +
                          " rad; pass the current state (or psi_valid = false)");
  const std::array<double, 16> pose0 = model.GetCartPose(q0);
  const planning::CartesianPath path = makePath(pose0, psi0, via, target);
  const double share = client::planShare(speed_ratio);
  client::JointSamples joints;
  const planning::CartesianTrajectory trajectory =
      client::planWithinJointLimits(call, path, share, XmateModelAccess::kinematics(model), q0, &joints);
  if (planning::duration(trajectory) <= 0) return true;
  client::LimitWatch watch(spec, robot.connection().remembered().limits, q0, &XmateModelAccess::kinematics(model));
  requireWithinLimits(call, client::checkJointPath(watch, joints));

  MotionClock clock;
  if (user_model) {
    // Joint position mode, IK every cycle from the previous command (and, after a stall of the
    // loop, for the two cycles before: the bridge needs the plan's rates there).
    std::array<double, 7> q_prev = q0;
    client::StallBridge bridge(spec.dof, client::jointBridgeLimits(spec, share));
    robot.startMove(CM::kJointPosition, MM::kJointPosition);
    client::controlByMessageId(robot, JointControl([&](RobotState s) -> JointPositions {
      const bool starting = !clock.started;
      const double t = clock.at(s);
      if (starting && clock.started) bridge.startAt(s.message_id, s.q_c);
      bool plan_finished = false;
      const client::StallBridge::Vec q = bridge.command(s.message_id, [&](int k) {
        const planning::CartesianSample sample = planning::sampleTrajectory(trajectory, std::max(0.0, t - k * kDt));
        if (k == 0) plan_finished = sample.finished;
        std::array<double, 7> ik{};
        const int rc = model.GetJointPos(planning::poseToRowMajor(sample.pose), sample.psi, q_prev, ik);
        if (rc != XmateModel::kIkOk)
          throw MotionException(std::string(call) + ": IK failed during the motion: " + client::ikFailureText(rc) +
                                " (IK code " + std::to_string(rc) + "); the motion was stopped");
        return ik;
      });
      JointPositions out;
      out.q = q;
      q_prev = q;
      out.motion_finished = plan_finished && !bridge.bridging();
      return out;
    }));
  } else {
    // Cartesian position mode: the controller solves IK; we send the pose and the arm angle.
    const Eigen::Matrix3d reference = trajectory.path.start.pose.linear();
    client::StallBridge bridge(7, client::cartesianBridgeLimits(share));
    robot.startMove(CM::kCartesianPosition, MM::kCartesianPosition);
    client::controlByMessageId(robot, CartesianControl([&](RobotState s) -> CartesianPose {
      const bool starting = !clock.started;
      const double t = clock.at(s);
      if (starting && clock.started)
        bridge.startAt(s.message_id, client::cartesianCoordinates(s.toolTobase_pos_c, s.psi_c, reference));
      bool plan_finished = false;
      const client::StallBridge::Vec c = bridge.command(s.message_id, [&](int k) {
        const planning::CartesianSample sample = planning::sampleTrajectory(trajectory, std::max(0.0, t - k * kDt));
        if (k == 0) plan_finished = sample.finished;
        return client::cartesianCoordinates(sample.pose, sample.psi, reference);
      });
      CartesianPose out;
      out.toolTobase_pos_c = planning::poseToRowMajor(client::poseFromCoordinates(c, reference));
      out.psi_valid = spec.dof == 7;
      out.psi_c = c[6];
      out.motion_finished = plan_finished && !bridge.bridging();
      return out;
    }));
  }
  return true;
}

}  // namespace

bool MOVEJ(double speed_ratio, const std::array<double, 7>& q_start, const std::array<double, 7>& q_target,
           Robot& robot) {
  const char* call = "MOVEJ";
  client::requireSpeedRatio(call, speed_ratio);
  const model::RobotSpec& spec = model::robotSpec(robot.type());
  requireFinite(call, "q_target", q_target, spec.dof);
  requireWithinJointRange(call, q_target, spec);
  robot.connection().ensureOpen();
  const client::StandstillWait moved = robot.connection().awaitStandstill(call);  // after a stop: plan from rest
  const RobotState state = robot.receiveRobotState();
  client::requireStartJoints(call, q_start, state.q, spec.dof, moved);
  const client::MotionLimits limits = robot.connection().remembered().limits;
  if (limits.box_active) {
    XmateModel model = pathModel(robot, nullptr);
    client::LimitWatch watch(spec, limits, state.q, &XmateModelAccess::kinematics(model));
    requireWithinLimits(call, client::checkJointLine(watch, state.q, q_target, spec.dof));
  } else {
    client::LimitWatch watch(spec, limits, state.q, nullptr);
    requireWithinLimits(call, client::checkJointLine(watch, state.q, q_target, spec.dof));
  }

  std::array<double, 7> q0 = state.q;
  const double share = client::planShare(speed_ratio);
  JointMotionGenerator generator(share, q_target, robot.type());
  generator.calculateSynchronizedValues_joint(q0);
  if (generator.GetTime() <= 0) return true;

  MotionClock clock;
  client::StallBridge bridge(spec.dof, client::jointBridgeLimits(spec, share));
  robot.startMove(CM::kJointPosition, MM::kJointPosition);
  client::controlByMessageId(robot, JointControl([&](RobotState s) -> JointPositions {
    const bool starting = !clock.started;
    const double t = clock.at(s);
    if (starting && clock.started) {
      q0 = s.q;  // where the motion really starts; re-plans only if the robot moved meanwhile
      generator.calculateSynchronizedValues_joint(q0);
      bridge.startAt(s.message_id, s.q_c);  // the "hold still" command the controller has now
    }
    bool plan_finished = false;
    const client::StallBridge::Vec q = bridge.command(s.message_id, [&](int k) {
      std::array<double, 7> delta{}, plan{};
      const bool finished = generator.calculateDesiredValues_joint(std::max(0.0, t - k * kDt), delta);
      if (k == 0) plan_finished = finished;
      for (int i = 0; i < spec.dof; ++i) plan[i] = finished ? q_target[i] : q0[i] + delta[i];
      return plan;
    });
    JointPositions out;
    for (int i = 0; i < spec.dof; ++i) out.q[i] = q[i];
    out.motion_finished = plan_finished && !bridge.bridging();
    return out;
  }));
  return true;
}

bool MOVEL(double speed_ratio, cart_pos& start, cart_pos& target, Robot& robot) {
  return moveCartesian("MOVEL", speed_ratio, start, nullptr, target, robot, nullptr);
}

bool MOVEL(double speed_ratio, cart_pos& start, cart_pos& target, Robot& robot, XmateModel& model) {
  return moveCartesian("MOVEL", speed_ratio, start, nullptr, target, robot, &model);
}

bool MOVEC(double speed_ratio, cart_pos& start, cart_pos& mid, cart_pos& target, Robot& robot) {
  return moveCartesian("MOVEC", speed_ratio, start, &mid, target, robot, nullptr);
}

bool MOVEC(double speed_ratio, cart_pos& start, cart_pos& mid, cart_pos& target, Robot& robot, XmateModel& model) {
  return moveCartesian("MOVEC", speed_ratio, start, &mid, target, robot, &model);
}

}  // namespace xmate
