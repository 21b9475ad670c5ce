// SPDX-License-Identifier: Apache-2.0
// The limits a motion must stay within before anything moves, as the client knows them: the joint
// range, the soft limits set with Robot::setJointLimit and the safety box set with
// setCartesianLimit. A path is followed sample by sample from where the arm is; a joint (or the
// TCP) that starts beyond a limit may only come back towards it, as the controller allows.
// MOVEJ/MOVEL/MOVEC and the teach executor refuse a motion that breaks one, naming the joint or the
// face of the box, the limit and the value -- the same answer whatever the timing.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "model/arm_kinematics.h"
#include "model/robot_spec.h"

namespace xmate::client {

// What Robot::setJointLimit and setCartesianLimit last set on this session (Connection::Remembered).
struct MotionLimits {
  bool has_soft_limits = false;
  std::array<double, 7> soft_lower{}, soft_upper{};  // rad
  bool box_active = false;
  std::array<double, 3> box_size{};                  // full edge lengths, m
  std::array<double, 16> box_frame{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // centre, row-major
};

// Follows the samples of one motion. Not real-time: used while planning.
class LimitWatch {
 public:
  // q_start: where the arm is; model: the robot's kinematics with its tool, for the TCP in the box
  // (needed only when limits.box_active; it must outlive the watch).
  LimitWatch(const model::RobotSpec& spec, const MotionLimits& limits, const std::array<double, 7>& q_start,
             const model::ArmKinematics* model);

  // "" while the motion may go on to q; else what it breaks: "joint 3 would reach 125.0 deg, beyond
  // its soft upper limit of 120.0 deg". `where` is appended ("at its target", "62 % of the way").
  std::string check(const std::array<double, 7>& q, const std::string& where);

 private:
  std::string checkJoints(const std::array<double, 7>& q) const;
  std::string checkBox(const Eigen::Vector3d& local) const;
  void narrow(const std::array<double, 7>& q, const Eigen::Vector3d& local);

  const model::RobotSpec& spec_;
  const model::ArmKinematics* model_;
  MotionLimits limits_;
  Eigen::Isometry3d box_to_base_ = Eigen::Isometry3d::Identity();
  // What is allowed: the limits, or where a joint / the TCP beyond one is now (narrowed as it returns).
  std::array<double, 7> lower_{}, upper_{}, soft_lower_{}, soft_upper_{};
  Eigen::Vector3d box_lower_ = Eigen::Vector3d::Zero(), box_upper_ = Eigen::Vector3d::Zero();
};

// Samples the joint line from q_start to q_target (as MOVEJ moves: every joint in proportion) and
// returns the first problem ("" if none), with "at the target" or "N % of the way".
std::string checkJointLine(LimitWatch& watch, const std::array<double, 7>& q_start,
                           const std::array<double, 7>& q_target, int dof);

// Follows joint samples of a path (the arm starts at the watch's q_start, then goes through each)
// and returns the first problem ("" if none): the target's (the last sample, "at the target")
// if it has one, else the first on the way ("N % of the way").
std::string checkJointPath(LimitWatch& watch, const std::vector<std::array<double, 7>>& samples);

}  // namespace xmate::client
