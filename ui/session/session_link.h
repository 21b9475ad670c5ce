// SPDX-License-Identifier: Apache-2.0
// Link: what one open session holds (an xMate's robot client and embedded simulator, or a KUKA's
// RSI arm, F/T sensor and simulated KRC; the arm::Arm over either; worker threads), how it is opened
// (on a background thread) and torn down. Used by session.cpp only.
#pragma once

#include <array>
#include <chrono>
#include <atomic>
#include <memory>
#include <string>

#include <xmate/model.h>
#include <xmate/robot.h>

#include "arm/rsi_arm.h"
#include "ft/netft.h"
#include "session/job_worker.h"
#include "session/session.h"
#include "sim/ft_sensor.h"
#include "sim/krc_server.h"
#include "sim/server.h"

namespace rci::ui {

// The motion worker's shared flags for the session's one motion at a time: set by the GUI thread,
// read by the job and its real-time callback (lock-free atomics).
struct MotionFlags {
  std::atomic<bool> busy{false};          // a runArmMotion() job is queued or running
  std::atomic<bool> stop{false};          // the current job's stop token (cleared when one is queued)
  std::atomic<int64_t> heartbeat_ns{0};   // steady clock of the GUI thread's last display tick
};

struct Link {
  SessionTarget target;
  // An xMate:
  std::unique_ptr<xmate::sim::Server> server;  // kSimulator only
  std::unique_ptr<xmate::Robot> robot;
  std::unique_ptr<xmate::XmateModel> model;    // GUI thread only (external joint torques)
  // A KUKA:
  std::unique_ptr<xmate::sim::SimulatedFtSensor> ft_simulator;  // kKukaSimulator only
  std::unique_ptr<xmate::arm::RsiArm> rsi;
  std::unique_ptr<xmate::sim::KrcServer> krc;  // kKukaSimulator only
  std::unique_ptr<xmate::ft::NetFtClient> ft;         // when a sensor is configured (always in the simulator)
  // Either: the RCI arm over `robot`, or `rsi` itself.
  std::unique_ptr<xmate::arm::Arm> rci_arm;
  xmate::arm::Arm* arm = nullptr;
  std::unique_ptr<JobWorker> commands;         // run() jobs and the 5 Hz poll
  std::unique_ptr<JobWorker> motions;          // runArmMotion() jobs
  std::atomic<bool> closing{false};            // set by shutdownLink: a running reconnect gives up
  MotionFlags motion;
};

// xMate: starts the simulator (kSimulator) and connects the robot client. KUKA: reads the RSI
// files and starts listening for the robot (and the simulated KRC and sensor, kKukaSimulator; the
// sensor's client when one is configured). Blocking: call it off the GUI thread. Throws
// std::runtime_error whose message says what failed and what to do.
std::unique_ptr<Link> openLink(const SessionTarget& target);

// How long shutdownLink lets a motion end by itself after its stop token was set, before it sends
// StopMove and closes the connection under it; and how long it then waits for each worker.
inline constexpr std::chrono::milliseconds kMotionStopWait{1500};
inline constexpr std::chrono::milliseconds kWorkerEndWait{3000};

// Ends the session: sets the motion's stop token and waits (kMotionStopWait) for the motion to
// end; if it did not, sends StopMove; then stops the simulator, closes the connection (which ends
// any Control() and TCP request) and joins the workers (kWorkerEndWait each). Blocking, bounded:
// returns false when a worker did not end -- its thread was abandoned and the link must then be
// kept alive (leaked) by the caller, since that thread may still use it.
bool shutdownLink(Link& link);

// After the controller stopped sending states: opens the session again (the controller rebooted,
// a cable was re-plugged). Blocking, on the command worker. Gives up when link.closing is set, when
// the embedded simulator was killed, or after 10 s (simulator) / 60 s (robot). true on success.
bool reconnectLink(Link& link);

// What the command worker polls while idle (~5 Hz). ok is false if the controller did not answer.
struct PollResult {
  bool ok = false;
  int motor_state = 0;
  int safety_stop = 1;
  std::array<bool, 6> digital_in{};
  std::array<double, 16> tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  uint64_t kuka_inputs = 0;  // a KUKA: bit k = input k of the arm's inputNames()
};
// Runs on the command worker thread (it owns the robot's TCP commands).
PollResult pollRobot(xmate::Robot& robot);
// A KUKA's wired inputs (the newest <Rob>); the command worker.
PollResult pollArm(xmate::arm::Arm& arm);

// tau = J(q)^T * wrench: the external wrench at the TCP mapped to joint torques.
std::array<double, 7> externalJointTorques(xmate::XmateModel& model, const std::array<double, 7>& q,
                                           const std::array<double, 6>& wrench);

}  // namespace rci::ui
