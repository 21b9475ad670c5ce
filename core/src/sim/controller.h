// SPDX-License-Identifier: Apache-2.0
// The simulated robot controller's logic and physics, without any I/O: it answers TCP requests,
// advances one 1 ms cycle at a time, and reports the RobotState to send. Single-threaded: the
// server (sim/server.h) serialises every call. Tests drive it directly; rci-sim, the GUI and the
// client tests reach it over real sockets through the server.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <xmate/rci_types.h>
#include <xmate/types.h>

#include "protocol/tcp_codec.h"

namespace xmate::sim {

struct SimConfig {
  XmateType type = XMATE7_PRO;
  // Joint positions at power-up (rad). Default: a comfortable, non-singular pose.
  std::array<double, 7> initial_q{0.0, 0.5236, 0.0, 1.0472, 0.0, 1.5708, 0.0};
  bool motors_on_at_start = false;
  bool do_to_di_loopback = false;  // DO k drives DI k (lets IO be tested without wiring)
  // Consecutive lost commands during motion that set kInstabilityDetection (manual: 10-20).
  int instability_threshold = 15;
  // Answer Connect with kIncompatibleLibraryVersion (to test the client's handling).
  bool reject_connect_as_incompatible = false;
};

// Snapshot of everything an operator or a test may want to see that is not in RobotState.
struct SimStatus {
  bool motors_on = false;
  int safety_stop = 1;         // 1 none, 2 ESTOP, 3 GSTOP (API numbering)
  bool dragging = false;
  bool motion_active = false;  // between a successful StartMove and the end of the motion
  std::array<bool, 6> digital_out{};
  std::array<bool, 6> digital_in{};
  std::array<double, 6> external_wrench{};  // applied by the scene, base frame, at the TCP
  uint64_t cycles = 0;
  uint64_t lost_commands = 0;  // since power-up
  // Added for the GUI, rci-sim and tests:
  uint64_t consecutive_lost_commands = 0;        // in the running motion
  std::array<double, 7> external_joint_torque{};  // the collision detector's estimate, Nm
  double actual_payload_mass = 0;                // kg, what really hangs on the flange
  bool actual_payload_follows_load = true;       // false after setActualPayload()
};

// How far beyond the hardware limits placeArm may put a joint, rad (about 11.5 deg).
inline constexpr double kPlaceBeyondHardware = 0.2;

class Controller {
 public:
  // Loads the model's robot description (URDF and inertias, model/urdf_loader.h); throws
  // std::runtime_error naming the places it looked if the description cannot be found.
  explicit Controller(const SimConfig& config = {});
  ~Controller();
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  // ---- TCP command channel ------------------------------------------------------------------
  // One request payload (starting with its Command code) in, the whole response frame out
  // (echoing sequence). Unknown or malformed requests get a response too (never a crash).
  protocol::Frame handleRequest(uint32_t sequence, const uint8_t* payload, size_t size);
  // True once RebootRobot was accepted: the server drops the session and, after a pause,
  // replaces this controller with a fresh one (tool, load and settings back to defaults).
  bool rebootRequested() const;

  // ---- 1 kHz cycle ------------------------------------------------------------------------------
  // The state to send now. message_id increases by one per step().
  const RCI::robot::RobotState& state() const;
  // True while a motion is active and each state must be answered by a RobotCommand.
  bool expectsCommand() const;
  // Advances one cycle of 1 ms. command: the client's answer to state() if it arrived in time
  // (its message_id should equal state().message_id), nullptr if it was lost or late.
  void step(const RCI::robot::RobotCommand* command);

  // ---- Scene and faults (also reachable through rci-sim's control port) -------------------------
  // External wrench [F; M] in the base frame acting at the TCP, N and Nm; stays until changed.
  void setExternalWrench(const std::array<double, 6>& wrench);
  void setEmergencyStop(bool pressed);
  void setGuardStop(bool active);
  void setDigitalInput(int index, bool level);  // 0..5 = DI0_0..DI1_1
  void setDoToDiLoopback(bool on);
  // What really hangs on the flange (flange frame: kg, m, kg m^2 about the centre of mass,
  // row-major). Until this is called the actual payload is whatever setLoad configured; a
  // different one makes gravity compensation and the collision detector see the difference, as a
  // wrong setLoad does on the real robot. Throws std::invalid_argument for a negative or
  // non-finite mass, a non-finite centre or an inertia that is not finite and symmetric.
  void setActualPayload(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia);
  // Back to "the actual payload is the configured load".
  void followConfiguredLoad();
  // Puts the arm at q (rad), at rest, as if it had been moved there while unpowered -- also beyond
  // the soft and hardware limits, by up to kPlaceBeyondHardware (a sagging payload, a drifted
  // robot, fault injection). A running motion or hand guiding ends (as by a stop); a powered arm is
  // then held at q. Throws std::invalid_argument for a non-finite q or one farther out than that.
  void placeArm(const std::array<double, 7>& q);

  // Allocation-free snapshot (safe to take every cycle).
  SimStatus status() const;
  const SimConfig& config() const;
  // Why the last refused TCP request was refused: a sentence naming the call, the value and the
  // rule ("" if nothing was refused yet). For logs, the GUI and tests.
  const std::string& lastRefusal() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace xmate::sim
