// SPDX-License-Identifier: Apache-2.0
// Shared helpers of the client tests: a simulator on a free loopback port (lock-step clock), a
// robot connected to it, bounded waits, and small motions that end with MotionFinished.
#pragma once

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include <xmate/robot.h>

#include "sim/server.h"
#include "state_compare.h"

namespace client_test {

struct SimOptions {
  xmate::XmateType type = xmate::XMATE7_PRO;
  bool motors_on = true;
  bool loopback_io = false;
  bool reject_connect = false;
  int reboot_pause_ms = 200;
  int instability_threshold = 15;
  // Lock-step: wall time the simulator waits for an answer before the cycle counts as lost. Keep it
  // below the client's 100 ms silence limit in tests that lose answers on purpose.
  int lockstep_timeout_ms = 200;
  xmate::sim::ClockMode clock = xmate::sim::ClockMode::kLockStep;
};

// A started simulator bound to 127.0.0.1 on a free port.
std::unique_ptr<xmate::sim::Server> startSim(const SimOptions& options = {});
// A robot for that simulator (not yet connected: the first call connects).
std::unique_ptr<xmate::Robot> robotFor(const xmate::sim::Server& server, xmate::XmateType type = xmate::XMATE7_PRO);
// A TCP port nobody listens on (bound and released again).
uint16_t unusedPort();

// Runs action on its own thread once the simulator reports a motion running (and `after_ms` more),
// so faults hit the middle of a motion; joins in the destructor.
class DuringMotion {
 public:
  DuringMotion(xmate::sim::Server& server, std::function<void()> action, int after_ms = 20);
  ~DuringMotion();
  DuringMotion(const DuringMotion&) = delete;
  DuringMotion& operator=(const DuringMotion&) = delete;
  bool fired() const { return *fired_; }

 private:
  std::shared_ptr<std::atomic<bool>> fired_ = std::make_shared<std::atomic<bool>>(false);
  std::thread thread_;
};

// Polls condition until it holds or limit_ms passes (a safety net, not a timing claim).
bool eventually(const std::function<bool()>& condition, int limit_ms = 10000);

// Runs call, retried while the controller answers "not possible" (CommandException) because the
// robot is still stopping from the previous motion or drag (a stop ramp takes a few cycles).
void whenReady(const std::function<void()>& call);
void startMoveWhenReady(xmate::Robot& robot, RCI::robot::StartMoveRequest::ControllerMode controller_mode,
                        RCI::robot::StartMoveRequest::MotionGeneratorMode motion_mode);

// Holds the joints where they are for `cycles` cycles, then ends with MotionFinished.
xmate::JointControl holdStill(int cycles, int* calls = nullptr);

// Runs MOVEJ-like joint motion from the robot's position by delta on joint `joint` with a smooth
// (7th-order) profile of `seconds`, through startMove + Control.
void smoothJointMove(xmate::Robot& robot, int joint, double delta, double seconds);

// ---- Stalls of the machine ------------------------------------------------------------------------
// A shared 2-vCPU VM now and then does not run the client's real-time thread for 15 ms or more,
// SCHED_FIFO or not (the hypervisor runs something else meanwhile), and the controller then stops
// the motion (kInstabilityDetection), as a real one would. The stop is right, and it is the
// machine's doing, not the library's. Tests on the real-time clock repeat such a motion from where
// it began, up to a budget per test function; a test function whose machine stalls more often than
// that is skipped with the count (it measured the machine, not the library). Every other failure,
// and a stop after a stall no longer than the one the test caused itself, still fails.
class MachineStalls {
 public:
  explicit MachineStalls(int budget = 3) : budget_(budget) {}
  // True, and counted, when `failure` (an exception's text) is the controller's stop after a stall
  // of the client's loop at least kMachineStallMarginMs longer than the `injected_ms` the test
  // caused, or after the whole machine froze (no state for the client's 100 ms silence limit).
  bool excuse(const std::string& failure, double injected_ms = 0);
  bool exhausted() const { return count_ > budget_; }
  int count() const { return count_; }
  // "the machine stalled the client's real-time thread N times ...; the first: <failure>".
  std::string summary() const;

 private:
  int budget_;
  int count_ = 0;
  std::string first_;
};

// A stall of the client's loop this much longer than the one a test injected is the machine's.
inline constexpr double kMachineStallMarginMs = 10.0;

// Runs `attempt` (returns "" when the motion completed, else what went wrong); after a stop the
// machine caused (stalls.excuse), recovers, drives back to the joint position the attempt began at
// and runs it again, until it completes, fails otherwise, or the budget is spent. Returns the last
// attempt's result. Callers then skip when stalls.exhausted() (SKIP_IF_THE_MACHINE_STALLED).
std::string excusingMachineStalls(xmate::Robot& robot, MachineStalls& stalls, double injected_ms,
                                  const std::function<std::string()>& attempt);

// In a Qt Test function: skips it once its machine stalled more often than the budget.
#define SKIP_IF_THE_MACHINE_STALLED(stalls)                        \
  do {                                                             \
    if ((stalls).exhausted()) QSKIP((stalls).summary().c_str());   \
  } while (false)

using rci_test::anyError;
using rci_test::distance;
using rci_test::maxAbsDiff;

}  // namespace client_test
