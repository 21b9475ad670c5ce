// SPDX-License-Identifier: Apache-2.0
// guide::AdmittanceGuide: hand guiding by a force/torque sensor on the flange, for arms without
// their own (a KUKA over RSI). Each controller cycle it reads the sensor, removes the bias and the
// tool's weight, applies a dead band and the chosen axes, moves a virtual mass-damper by the rest
// and streams the joints that follow it -- within the joint ranges, the axis speeds, the bounds
// the caller sets (RSI's correction limits) and a speed cap -- and comes to rest smoothly when the
// force is released, the operator stops, or the sensor falls silent (it then says why).
// docs/guiding.md.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

#include "arm/arm.h"
#include "model/arm_kinematics.h"
#include "net/seqlock.h"

namespace xmate::guide {

// Where the newest wrench comes from: Fx Fy Fz (N), Tx Ty Tz (Nm) in the sensor's frame (= the
// flange frame here), and when it arrived (net::monotonicNs). Lock-free, real-time safe.
class WrenchSource {
 public:
  virtual ~WrenchSource() = default;
  virtual bool read(std::array<double, 6>& wrench, int64_t& received_ns) const = 0;
};

// Which motions the force may cause, as the xMate's Drag panel offers them.
enum class GuideAxes { kTranslation, kRotation, kFree };

struct GuideParameters {
  GuideAxes axes = GuideAxes::kTranslation;
  double mass = 8.0;              // kg: virtual mass of translation
  double inertia = 0.4;           // kg m^2: virtual inertia of rotation
  double damping = 120.0;         // N s/m
  double rotational_damping = 4;  // N m s/rad
  double force_dead_band = 4.0;   // N: forces below it are ignored (and subtracted above it)
  double torque_dead_band = 0.4;  // Nm
  double max_speed = 0.25;        // m/s of the flange
  double max_angular_speed = 0.6; // rad/s
  double braking = 1.0;           // m/s^2 (and rad/s^2): how fast it stops when stopping
  double sensor_timeout_s = 0.1;  // no new reading for this long: the sensor fell silent
  double axis_speed_share = 0.5;  // of each axis's rated speed
};

// The tool hanging on the sensor: its weight is removed from every reading.
struct ToolWeight {
  double mass = 0;                        // kg
  std::array<double, 3> center{};         // m, centre of mass in the sensor (flange) frame
};

// The wrench the tool's weight causes at the sensor (sensor frame, N and Nm) with the flange at
// `flange_in_base` (row-major 4x4; gravity is -z of the base). Real-time safe.
std::array<double, 6> toolWeightAtSensor(const ToolWeight& tool, const std::array<double, 16>& flange_in_base);

// Why a guide ended.
enum class GuideEnd { kRunning, kOperator, kSensorSilent };
const char* describe(GuideEnd end);  // operator words: "stopped by the operator", ...

// What the guide is doing, for the window (any thread, lock-free).
struct GuideStatus {
  uint64_t cycles = 0;             // controller cycles guided so far (0: not started; the bias is taken at 1)
  std::array<double, 6> wrench{};  // the force and torque it acts on: bias and tool removed, base frame, N and Nm
  std::array<double, 6> velocity{};  // of the flange, base frame, m/s and rad/s
  int limited_axis = -1;           // an axis held at its range or bound this cycle (0-based), -1 none
  bool cannot_follow = false;      // the arm cannot move the way it is pushed here (the edge of its
                                   // reach, a singular pose): it holds still
  GuideEnd end = GuideEnd::kRunning;  // while it brakes to its end, already why
};

class AdmittanceGuide : public arm::JointMotion {
 public:
  // Set-up (allocates). `model`: the arm's (the guide works at the flange, where the sensor is: its
  // copy drops any tool). `cycle_s`: the controller's cycle (arm::Arm::cycleSeconds()).
  AdmittanceGuide(const model::ArmKinematics& model, const WrenchSource& sensor, double cycle_s,
                  GuideParameters parameters, ToolWeight tool = {});

  // Set-up: bounds the joints (rad) beyond the model's ranges, e.g. RSI's correction limits around
  // the pose RSI started at. Defaults: the model's ranges.
  void setJointBounds(const std::array<double, 7>& lower, const std::array<double, 7>& upper);

  // Any thread, lock-free: come to rest and end (GuideEnd::kOperator).
  void requestStop() { stop_.store(true, std::memory_order_release); }
  GuideStatus status() const;

  // The controller's cycle: no allocation, no lock. The first call takes the bias (the reading now,
  // less the tool's weight): start with nobody touching the tool.
  bool command(const arm::ArmSample& now, std::array<double, 7>& q) override;

 private:
  void stepVelocity(const std::array<double, 6>& wrench_base, double dt, bool stopping);

  model::ArmKinematics model_;
  const WrenchSource& sensor_;
  const GuideParameters parameters_;
  const ToolWeight tool_;
  double dt_;
  std::array<double, 7> lower_{}, upper_{};
  std::atomic<bool> stop_{false};
  // The controller thread's own.
  bool started_ = false;
  std::array<double, 6> bias_{};
  std::array<double, 7> q_{};
  std::array<double, 6> velocity_{};
  GuideEnd ending_ = GuideEnd::kRunning;
  GuideStatus now_;
  net::Seqlock<GuideStatus> status_;
};

}  // namespace xmate::guide
