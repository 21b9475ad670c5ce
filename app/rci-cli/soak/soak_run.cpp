// SPDX-License-Identifier: Apache-2.0
// runSoak (soak.h): the simulator with its random state loss, the robot, the CPU burners, and the
// loop of motions; after a failure the soak recovers as a program would and goes on.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <memory>
#include <optional>
#include <regex>
#include <thread>

#include <xmate/move.h>
#include <xmate/robot.h>

#include "client/connection.h"
#include "client/error_bits.h"
#include "net/cpu_burners.h"
#include "soak/soak.h"
#include "soak/soak_losses.h"
#include "soak/soak_motions.h"
#include "soak/soak_watchdog.h"

namespace rci_cli::soak {
namespace {

using Clock = std::chrono::steady_clock;

constexpr xmate::XmateType kType = xmate::XMATE7_PRO;
constexpr std::chrono::seconds kMotionDeadline{60};  // every motion takes a few seconds at most
constexpr double kRecoverySpeed = 0.3;
constexpr int kRecoveryMoves = 3;                     // tries to reach the next start after a failure
constexpr std::chrono::seconds kRecoveryPatience{5};  // automaticErrorRecovery refused (still stopping)
// Lock-step: how long a cycle waits for the client's answer before it counts as lost (a state the
// simulator dropped is not waited for: its answer cannot come). Below the client's 100 ms silence
// limit, so that a stalled client loses commands the way a real controller would count them.
constexpr int kLockStepTimeoutMs = 50;

std::unique_ptr<sim::Server> startSimulator(const SoakOptions& o) {
  auto config = sim::embeddedConfig(kType, o.lockstep ? sim::ClockMode::kLockStep : sim::ClockMode::kRealTime);
  config.sim.motors_on_at_start = true;
  config.lockstep_timeout_ms = kLockStepTimeoutMs;
  // A controller runs on its own real-time machine: the burners must not stall the simulator (it
  // would then send nothing for 100 ms, a failure the client cannot help). Refused without privileges.
  config.realtime = true;
  return sim::startEmbedded(std::move(config));
}

sim::StateLoss stateLossOf(const SoakOptions& o) {
  return {o.loss_percent / 100, o.pair_percent / 100, o.burst_states, o.burst_every_ms, o.seed};
}

// The client's counters summed over its sessions: a reconnect starts them from zero.
class ClientTotals {
 public:
  void read(const xmate::client::SessionCounters& now) {
    if (now.states_received < last_.states_received) {  // a new session
      base_received_ += last_.states_received;
      base_missed_ += last_.states_missed;
      base_dropped_ += last_.samples_dropped;
    }
    last_ = now;
  }
  void fill(SoakReport& report) const {
    report.client_states_received = base_received_ + last_.states_received;
    report.client_states_missed = base_missed_ + last_.states_missed;
    report.client_samples_dropped = base_dropped_ + last_.samples_dropped;
  }

 private:
  xmate::client::SessionCounters last_;
  uint64_t base_received_ = 0, base_missed_ = 0, base_dropped_ = 0;
};

uint64_t latestMessageId(xmate::Robot& robot) {
  RCI::robot::RobotState state;
  return robot.connection().latestState(state) ? state.message_id : 0;
}

void count(FailureGroup& group, const std::string& text) {
  if (group.count++ == 0) group.example = text;
}

void record(KindFigures& figures, const MotionResult& r) {
  ++figures.count;
  figures.wall_s += r.wall_s;
  figures.states_lost += r.states_lost;
  figures.longest_loss = std::max(figures.longest_loss, r.longest_loss);
  if (!r.failed) return;
  ++figures.failures;
  figures.stall_failures += r.after_stall;
  count(figures.failure_kinds[failureKind(r.failure)], r.failure);
}

// Runs `motion` under the watchdog and measures it: wall time, states lost, failure text.
template <class Motion>
MotionResult measured(xmate::Robot& robot, Watchdog& watchdog, LossWatch& losses, Motion&& motion) {
  MotionResult r;
  const uint64_t from = latestMessageId(robot);
  const Clock::time_point start = Clock::now();
  watchdog.arm(kMotionDeadline);
  try {
    motion();
  } catch (const std::exception& e) {
    r.failed = true;
    r.failure = e.what();
  }
  if (watchdog.disarm()) {
    r.failed = true;
    r.failure = "the motion did not end within " + std::to_string(kMotionDeadline.count()) +
                " s: the soak closed the session (" + r.failure + ")";
  }
  r.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  const Losses lost = losses.between(from, latestMessageId(robot));
  r.states_lost = lost.states;
  r.longest_loss = lost.longest;
  return r;
}

// Marks a measured motion's failure as one after a stall (MotionResult::after_stall) and counts a
// stall it names; `stalled` carries the episode from one motion to the next until one succeeds.
void classify(MotionResult& r, bool& stalled, SoakReport& report) {
  const bool names_stall = r.failed && isStallFailure(r.failure);
  report.stalls += names_stall;
  r.after_stall = r.failed && (stalled || names_stall);
  stalled = r.after_stall;
}

// A refused recovery call, counted by its kind.
void noteRefusal(SoakReport& report, const char* call, const std::exception& e) {
  count(report.recovery_refusals[std::string(call) + ": " + failureKind(e.what())], e.what());
}

// What a program does after a failure before it moves again: reconnect if the session is gone,
// clear the error (retried while the arm is still stopping), power the motors on.
void clearTheFailure(xmate::Robot& robot, SoakReport& report) {
  if (!robot.connection().isOpen()) {
    ++report.reconnects;
    robot.reconnect();
  }
  const Clock::time_point give_up = Clock::now() + kRecoveryPatience;
  for (;;) {
    try {
      robot.automaticErrorRecovery();
      break;
    } catch (const std::exception& e) {
      noteRefusal(report, "automaticErrorRecovery", e);
      if (Clock::now() > give_up) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  try {
    robot.setMotorPower(1);
  } catch (const std::exception& e) {
    noteRefusal(report, "setMotorPower", e);
  }
}

// After a failure: clear it and move slowly to where motion `index` starts (a few tries).
void recover(long index, xmate::Robot& robot, const Joints& start, Watchdog& watchdog, LossWatch& losses,
             bool& stalled, SoakReport& report, const std::function<void(const MotionResult&)>& on_motion) {
  for (int attempt = 0; attempt < kRecoveryMoves; ++attempt) {
    clearTheFailure(robot, report);
    MotionResult r = measured(robot, watchdog, losses, [&] {
      if (!xmate::MOVEJ(kRecoverySpeed, robot.receiveRobotState().q, start, robot))
        throw std::runtime_error("MOVEJ did not reach the next motion's start");
    });
    r.index = index;
    r.kind = MotionKind::kMoveJ;
    r.recovery = true;
    classify(r, stalled, report);
    record(report.recovery, r);
    if (on_motion) on_motion(r);
    if (!r.failed) return;
  }
}

// After the last motion: the totals of the client, the simulator and the lost states.
void finish(SoakReport& report, sim::Server& server, xmate::Robot& robot, LossWatch& losses, ClientTotals& client) {
  server.setStateLoss({});
  std::this_thread::sleep_for(std::chrono::milliseconds(150));  // the client's timing is refreshed every 100 ms
  client.read(robot.connection().timing().counters);
  client.fill(report);
  uint64_t in_motions = report.recovery.states_lost;
  for (const KindFigures& k : report.kinds) in_motions += k.states_lost;
  const uint64_t all = losses.total().states;
  report.states_lost_idle = all > in_motions ? all - in_motions : 0;
  report.simulator = server.status().counters;
}

}  // namespace

SoakReport runSoak(const SoakOptions& options, const std::function<void(const MotionResult&)>& on_motion) {
  SoakReport report;
  report.options = options;
  const Clock::time_point start = Clock::now();
  std::unique_ptr<sim::Server> server = startSimulator(options);
  xmate::Robot robot("127.0.0.1", server->port(), kType);
  robot.connect();
  robot.setMotorPower(1);
  report.client_realtime = robot.connection().realtimeStatus().describe();
  report.simulator_realtime = server->status().realtime;
  const Waypoints at = waypointsFrom(kType, robot.receiveRobotState().q);
  LossWatch losses(robot.connection());
  Watchdog watchdog(robot);
  xmate::teach::Executor executor;  // one for every PATH, as the window's Program panel keeps one
  ClientTotals client;
  std::optional<xmate::net::CpuBurners> burners;
  if (options.burners) burners.emplace(2);
  server->setStateLoss(stateLossOf(options));

  bool displaced = false;  // the last motion failed: the arm is not where the next one starts
  bool stalled = false;    // ... after a stall of the machine (MotionResult::after_stall)
  for (long i = 0; i < options.motions; ++i) {
    if (displaced) recover(i, robot, startAt(i, at), watchdog, losses, stalled, report, on_motion);
    MotionResult r = measured(robot, watchdog, losses, [&] { runMotionAt(i, robot, executor, at); });
    r.index = i;
    r.kind = kindAt(i);
    classify(r, stalled, report);
    record(report.kinds[size_t(r.kind)], r);
    client.read(robot.connection().timing().counters);
    if (on_motion) on_motion(r);
    displaced = r.failed;
  }
  finish(report, *server, robot, losses, client);
  report.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  return report;
}

long SoakReport::motions() const {
  long n = 0;
  for (const KindFigures& k : kinds) n += k.count;
  return n;
}

long SoakReport::failures() const {
  long n = 0;
  for (const KindFigures& k : kinds) n += k.failures;
  return n;
}

long SoakReport::stallFailures() const {
  long n = 0;
  for (const KindFigures& k : kinds) n += k.stall_failures;
  return n;
}

bool isStallFailure(const std::string& text) {
  return text.find("real-time loop stalled for") != std::string::npos ||
         text.find("no state from the controller for") != std::string::npos;
}

std::string failureKind(const std::string& text) {
  std::string bits;
  for (int bit = 0; bit < xmate::client::kErrorBitCount; ++bit) {
    const std::string name = xmate::client::errorBitName(bit);
    const size_t at = text.find(name);
    const size_t end = at + name.size();
    if (at != std::string::npos && (end == text.size() || !std::isalnum(static_cast<unsigned char>(text[end]))))
      bits += (bits.empty() ? "" : "+") + name;
  }
  if (!bits.empty()) return bits;
  static const std::regex number(R"(\d+(\.\d+)?(e[-+]?\d+)?)");  // "100", "0.001706", "1e-3"
  return std::regex_replace(text, number, "#").substr(0, 100);
}

}  // namespace rci_cli::soak
