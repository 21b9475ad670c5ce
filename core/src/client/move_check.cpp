// SPDX-License-Identifier: Apache-2.0
// Start checks and the joint-space sweep of a Cartesian trajectory (move_check.h).
#include "client/move_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include <xmate/exception.h>

#include "planning/cartesian_pose.h"

namespace xmate::client {
namespace {

constexpr double kDt = 1e-3;               // the RCI cycle: the controller sees the motion at this rate
constexpr double kRetimeMargin = 1.05;     // re-timed moves aim 5 % under the limit
constexpr int kMaxRetimes = 8;

std::string fmt(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, format, a, b, c, d);
  return buf;
}

}  // namespace

void requireSpeedRatio(const char* call, double speed_ratio) {
  if (!(std::isfinite(speed_ratio) && speed_ratio > 0 && speed_ratio <= 1))
    throw std::invalid_argument(std::string(call) + ": speed_ratio = " + fmt("%g", speed_ratio) +
                                " is outside (0, 1]; pass e.g. 0.2");
}

void requireStartJoints(const char* call, const std::array<double, 7>& q_start, const std::array<double, 7>& q_actual,
                        int dof, const StandstillWait& moved) {
  for (int i = 0; i < dof; ++i) {
    if (!std::isfinite(q_start[i]))
      throw std::invalid_argument(std::string(call) + ": q_start[" + std::to_string(i) + "] is not a finite number");
    const double d = std::abs(q_start[i] - q_actual[i]);
    if (d > kStartJointTolerance + moved.joint_travel)
      throw MotionException(std::string(call) + ": q_start[" + std::to_string(i) + "] = " + fmt("%.6f", q_start[i]) +
                            " rad is " + fmt("%.6f", d) + " rad from the robot's position " +
                            fmt("%.6f", q_actual[i]) + " (more than 1e-3 rad); pass the current state, "
                            "e.g. robot.receiveRobotState().q");
  }
}

void requireStartPose(const char* call, const std::array<double, 16>& start, const std::array<double, 16>& actual,
                      const StandstillWait& moved) {
  const Eigen::Isometry3d a = planning::poseFromRowMajor(actual, "the robot's TCP pose");
  const Eigen::Isometry3d s = planning::poseFromRowMajor(start, (std::string(call) + " start pose").c_str());
  const double distance = (s.translation() - a.translation()).norm();
  const double angle = Eigen::AngleAxisd(a.linear().transpose() * s.linear()).angle();
  if (distance > kStartPositionTolerance + moved.tcp_travel || angle > kStartRotationTolerance + moved.rotation_travel)
    throw MotionException(std::string(call) + ": the start pose is " + fmt("%.2f", distance * 1000) + " mm and " +
                          fmt("%.4f", angle) + " rad from the robot's TCP pose (at most 1 mm and 1e-3 rad); pass the "
                          "current state, e.g. start.pos = robot.receiveRobotState().toolTobase_pos_m");
}

double JointSweep::worst() const { return std::max({velocity_ratio, acceleration_ratio, jerk_ratio}); }

const char* ikFailureText(int code) {
  switch (code) {
    case XmateModel::kIkTooFar: return "the pose is beyond the arm's reach";
    case XmateModel::kIkTooClose: return "the pose is too close to the shoulder for the elbow to fold";
    case XmateModel::kIkInvalidPose: return "the pose is not a rigid transform";
    case XmateModel::kIkArmJointTooFast: return "an arm joint would exceed its rated speed";
    case XmateModel::kIkWristJointTooFast: return "a wrist joint would exceed its rated speed";
    case XmateModel::kIkAboveSoftLimit: return "a joint would go above its soft limit";
    case XmateModel::kIkBelowSoftLimit: return "a joint would go below its soft limit";
    case XmateModel::kIkSingular: return "the pose is singular (stretched arm or aligned wrist axes)";
  }
  return "inverse kinematics failed";
}

JointSweep sweepTrajectory(const char* call, const planning::CartesianTrajectory& trajectory,
                           const model::ArmKinematics& model, const std::array<double, 7>& q_start, double speed_ratio,
                           JointSamples* joints) {
  const model::RobotSpec& spec = model.spec();
  const int dof = spec.dof;
  const double total = planning::duration(trajectory);
  const int steps = int(std::ceil(total / kDt - 1e-9));
  std::array<double, 7> q_prev = q_start, v_prev{}, a_prev{};
  JointSweep sweep;
  if (joints) {
    joints->clear();
    joints->reserve(size_t(steps) + 1);
    joints->push_back(q_start);
  }
  for (int k = 1; k <= steps; ++k) {
    const planning::CartesianSample sample = planning::sampleTrajectory(trajectory, k * kDt);
    std::array<double, 7> q{};
    const int rc = model.GetJointPos(planning::poseToRowMajor(sample.pose), sample.psi, q_prev, q);
    if (rc != XmateModel::kIkOk) {
      const Eigen::Vector3d p = sample.pose.translation();
      throw MotionException(std::string(call) + ": the path cannot be followed at " +
                            fmt("%.0f%% of its duration (t = %.3f s of %.3f s), TCP at (%.3f, ", 100.0 * k * kDt / total,
                                k * kDt, total, p.x()) +
                            fmt("%.3f, %.3f) m: ", p.y(), p.z()) + ikFailureText(rc) + " (IK code " +
                            std::to_string(rc) + "). Choose start, via and target poses inside the workspace and "
                            "away from singular poses, or move in joint space with MOVEJ");
    }
    for (int i = 0; i < dof; ++i) {
      const double v = (q[i] - q_prev[i]) / kDt, a = (v - v_prev[i]) / kDt, j = (a - a_prev[i]) / kDt;
      const double before = sweep.worst();
      sweep.velocity_ratio = std::max(sweep.velocity_ratio, std::abs(v) / (spec.dq_max[i] * speed_ratio));
      sweep.acceleration_ratio = std::max(sweep.acceleration_ratio, std::abs(a) / (spec.ddq_max[i] * kFullSpeedShare));
      sweep.jerk_ratio = std::max(sweep.jerk_ratio, std::abs(j) / (spec.jerk_max[i] * kFullSpeedShare));
      if (sweep.worst() > before) {
        const Eigen::Vector3d p = sample.pose.translation();
        sweep.worst_time = k * kDt;
        sweep.worst_joint = i;
        sweep.worst_tcp = {p.x(), p.y(), p.z()};
      }
      v_prev[i] = v;
      a_prev[i] = a;
    }
    q_prev = q;
    if (joints) joints->push_back(q);
  }
  return sweep;
}

planning::CartesianTrajectory planWithinJointLimits(const char* call, const planning::CartesianPath& path,
                                                    double speed_ratio, const model::ArmKinematics& model,
                                                    const std::array<double, 7>& q_start, JointSamples* joints) {
  double timing_ratio = speed_ratio;
  JointSweep sweep;
  double total = 0, slowdown = 1;
  for (int attempt = 0; attempt < kMaxRetimes && timing_ratio >= speed_ratio / kMaxSlowdown; ++attempt) {
    planning::CartesianTrajectory trajectory = planning::timePath(path, timing_ratio);
    sweep = sweepTrajectory(call, trajectory, model, q_start, speed_ratio, joints);
    if (sweep.worst() <= 1.0) return trajectory;
    // Too fast in joint space (typically near a singularity): slow the whole move down.
    total = planning::duration(trajectory);
    slowdown = speed_ratio / timing_ratio;
    timing_ratio /= sweep.worst() * kRetimeMargin;
  }
  throw MotionException(std::string(call) + ": the path passes too close to a singular pose: at " +
                        fmt("%.0f%% of its duration (TCP at (%.3f, ", 100.0 * sweep.worst_time / total,
                            sweep.worst_tcp[0]) +
                        fmt("%.3f, %.3f) m), ", sweep.worst_tcp[1], sweep.worst_tcp[2]) +
                        (slowdown < 1.05 ? std::string("at the requested speed, ")
                                         : fmt("even re-timed %.1f times slower, ", slowdown)) +
                        "joint " + std::to_string(sweep.worst_joint + 1) +
                        fmt(" would need %.1f times its speed, acceleration or jerk limit (at most %.0f times slower "
                            "is allowed). Choose poses farther from the singularity (stretched arm, aligned wrist "
                            "axes) or move in joint space with MOVEJ",
                            sweep.worst(), kMaxSlowdown));
}

}  // namespace xmate::client
