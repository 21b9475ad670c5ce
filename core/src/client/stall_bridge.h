// SPDX-License-Identifier: Apache-2.0
// StallBridge: what a motion commands after a stall of the client's loop. While commands are lost
// the controller continues its position target along the last commanded velocity and acceleration
// (docs/simulator_controller.md, "Lost commands"); a plan re-synchronised to the controller's clock
// (message_id) is somewhere else by then, and jumping onto it would be a step of the servo's
// target. The bridge starts the first command after the gap where that extrapolation is (same
// position, velocity and acceleration), then brings the command back onto the plan with a
// third-order tracker whose jerk is limited to a reserve and whose total acceleration stays within
// the limits -- a rate limiter against the controller's own command (docs/reliability.md). The
// total velocity is guarded too: the acceleration towards the velocity limit is held to what the
// jerk reserve can still brake before reaching it.
// Allocation-free and lock-free: made for the real-time callbacks of MOVEJ/MOVEL/MOVEC and the
// teach executor.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Geometry>

#include "model/robot_spec.h"

namespace xmate::client {

class StallBridge {
 public:
  static constexpr int kMaxDims = 7;
  using Vec = std::array<double, kMaxDims>;

  // Coordinates are limited in groups (a joint alone; the three of a Cartesian translation or
  // rotation together, as the controller limits the norm): the velocity and acceleration the group's
  // command must not exceed, its rated jerk, and the jerk the correction may always add on top of the
  // plan's own (the plan's reserve; where the plan's jerk leaves more of the rated one unused, the
  // correction may use that), all read at the group's first coordinate.
  struct Limits {
    Vec velocity{};  // 0: not guarded
    Vec acceleration{};
    Vec jerk{};
    Vec jerk_reserve{};
    std::array<int, kMaxDims> group{0, 1, 2, 3, 4, 5, 6};  // the first coordinate of each one's group
  };

  StallBridge(int dims, const Limits& limits);

  // The controller's command when the motion starts (the first state's q_c, or its
  // toolTobase_pos_c and psi_c), standing still before `message_id`: the first command continues
  // from there, and an offset to the plan's start (the robot crept between planning and StartMove,
  // the "hold still" answers used the measured position) is removed as smoothly as a stall's.
  void startAt(uint64_t message_id, const Vec& commanded);

  // The command to answer the state with `message_id`. plan_at(k) returns the plan's value k
  // cycles earlier (k = 0: at message_id; k = -1: the next cycle's); k = -1, 1 and 2 are asked for
  // only while a stall is being bridged. Without a gap in message_id (and no correction left) the
  // command is the plan itself.
  template <class PlanAt>
  Vec command(uint64_t message_id, const PlanAt& plan_at) {
    const Vec plan = plan_at(0);
    if (!needsPlanHistory(message_id)) return remember(message_id, plan);
    return remember(message_id, bridge(message_id, PlanWindow{plan_at(-1), plan, plan_at(1), plan_at(2)}));
  }

  // True while a correction is still being brought to zero (the motion must not end yet).
  bool bridging() const { return active_; }
  // Stalls bridged so far (gaps in message_id after the first three commands).
  int stalls() const { return stalls_; }

 private:
  // The plan around the cycle being answered: the next cycle's value, this one's, and the two before.
  struct PlanWindow {
    Vec next, now, before_1, before_2;
  };
  // The plan's rates the tracker needs, by divided differences of the window.
  struct PlanRates {
    Vec velocity{};           // at this cycle
    Vec acceleration{};       // second difference centred on this cycle: what the controller will
                              // measure with the next command
    Vec jerk{};               // third difference
  };
  PlanRates planRates(const PlanWindow& plan) const;

  bool needsPlanHistory(uint64_t message_id) const;
  Vec bridge(uint64_t message_id, const PlanWindow& plan);
  Vec remember(uint64_t message_id, const Vec& command);
  void startFromExtrapolation(uint64_t message_id, const PlanWindow& plan);
  void step(const PlanRates& plan);
  void guardVelocity(const Vec& velocity, Vec& jerk) const;
  double groupNorm(const Vec& v, int g) const;
  void limitGroups(Vec& v, const Vec& limit) const;
  void settleIfDone();

  int dims_;
  Limits limits_;
  // The last three commands sent (newest first) and their message_ids: what the controller got.
  std::array<Vec, 3> sent_{};
  std::array<uint64_t, 3> sent_id_{};
  int sent_count_ = 0;
  // The correction (command - plan): position, velocity, acceleration per coordinate.
  bool active_ = false;
  Vec e_{}, de_{}, dde_{};
  int stalls_ = 0;
  bool seeded_ = false;  // startAt() was called and the first command is still to come
};

// Limits for joint commands of a plan that uses `share` of the model's rated limits: the rated
// velocities and accelerations, and the unused share of the rated jerks (at least 10 %) as the reserve.
StallBridge::Limits jointBridgeLimits(const model::RobotSpec& spec, double share);
// Limits for Cartesian commands as cartesianCoordinates() lays them out (translation, rotation,
// arm angle): the controller's Cartesian velocities and accelerations, the unused share of the
// planner's jerks.
StallBridge::Limits cartesianBridgeLimits(double share);

// A Cartesian command as bridge coordinates: the position (m), the rotation vector of
// pose.linear() * reference^T (rad; continuous for rotations below pi from the reference, e.g. the
// path's start), the arm angle (rad). poseFromCoordinates is the inverse.
StallBridge::Vec cartesianCoordinates(const Eigen::Isometry3d& pose, double psi, const Eigen::Matrix3d& reference);
// The same for a row-major 4x4 pose as RobotState carries it (e.g. toolTobase_pos_c).
StallBridge::Vec cartesianCoordinates(const std::array<double, 16>& row_major, double psi,
                                      const Eigen::Matrix3d& reference);
Eigen::Isometry3d poseFromCoordinates(const StallBridge::Vec& coordinates, const Eigen::Matrix3d& reference);

}  // namespace xmate::client
