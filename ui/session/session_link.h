// SPDX-License-Identifier: Apache-2.0
// Link: what one open session holds (robot client, embedded simulator, model, worker threads), how
// it is opened (on a background thread) and torn down. Used by session.cpp only.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <string>

#include <xmate/model.h>
#include <xmate/robot.h>

#include "session/job_worker.h"
#include "session/session.h"
#include "sim/server.h"

namespace rci::ui {

struct Link {
  SessionTarget target;
  std::unique_ptr<xmate::sim::Server> server;  // kSimulator only
  std::unique_ptr<xmate::Robot> robot;
  std::unique_ptr<xmate::XmateModel> model;    // GUI thread only (external joint torques)
  std::unique_ptr<JobWorker> commands;         // run() jobs and the 5 Hz poll
  std::unique_ptr<JobWorker> motions;          // runMotion() jobs
  std::atomic<bool> closing{false};            // set by shutdownLink: a running reconnect gives up
};

// Starts the simulator (kSimulator) and connects the robot client. Blocking: call it off the GUI
// thread. Throws std::runtime_error whose message says what failed and what to do.
std::unique_ptr<Link> openLink(const SessionTarget& target);

// Stops the workers (the running jobs finish first), disconnects, stops the simulator. Blocking.
void shutdownLink(Link& link);

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
};
// Runs on the command worker thread (it owns the robot's TCP commands).
PollResult pollRobot(xmate::Robot& robot);

// tau = J(q)^T * wrench: the external wrench at the TCP mapped to joint torques.
std::array<double, 7> externalJointTorques(xmate::XmateModel& model, const std::array<double, 7>& q,
                                           const std::array<double, 6>& wrench);

}  // namespace rci::ui
