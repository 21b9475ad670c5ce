// SPDX-License-Identifier: Apache-2.0
// The soak (`rci-cli bench soak`, tests/soak/test_soak): hundreds of mixed motions by xmate::Robot
// against the in-process simulator on its real-time clock while it loses states at random and two
// threads burn CPU; failures are recovered from as a program would and counted with their messages.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "sim/server.h"

namespace rci_cli::soak {

namespace sim = xmate::sim;

// The motions of a soak, in the order they take turns.
enum class MotionKind {
  kMoveJ,              // xmate::MOVEJ at speed 1.0
  kMoveL,              // xmate::MOVEL at speed 1.0
  kMoveC,              // xmate::MOVEC at speed 1.0
  kPath,               // a PATH instruction replayed by the teach Executor
  kCartesianCallback,  // the vendor manual's Cartesian arc, its own clock (time += 0.001 per call)
  kJointCallback,      // a joint-position cosine on a few joints, its own clock likewise
};
inline constexpr size_t kMotionKinds = 6;
const char* kindName(MotionKind kind);  // "MOVEJ", ..., "cartesian callback", "joint callback"

struct SoakOptions {
  long motions = 200;
  double loss_percent = 2;    // states lost at random (sim::StateLoss::probability, in %)
  double pair_percent = 30;   // of those losses, two states in a row
  int burst_states = 5;       // and a burst of this many states ...
  int burst_every_ms = 10'000;  // ... this often (0 and 0: no bursts)
  uint32_t seed = 1;
  bool burners = true;        // two threads burning CPU beside the soak
  bool lockstep = false;      // the simulator's lock-step clock instead: states are lost, never late
};

// One motion's outcome, as it ends.
struct MotionResult {
  long index = 0;  // 0-based, in the order run
  MotionKind kind = MotionKind::kMoveJ;
  bool recovery = false;         // a slow move to the start of motion `index` after a failure
  bool failed = false;
  // Failed after the machine stalled a thread: its message says so (isStallFailure), or it failed
  // in the recovery from such a failure, before any motion succeeded again.
  bool after_stall = false;
  std::string failure;           // the exception's text (or the executor's report message)
  double wall_s = 0;
  uint64_t states_lost = 0;      // message_id gaps the client saw during the motion
  uint64_t longest_loss = 0;     // the longest of them
};

// Failures of one kind (failureKind): how many, and the first one's text in full.
struct FailureGroup {
  long count = 0;
  std::string example;
};

// A motion kind's (or the recovery moves') figures over the soak.
struct KindFigures {
  long count = 0;
  long failures = 0;
  long stall_failures = 0;  // of those, after the machine stalled a thread (MotionResult::after_stall)
  uint64_t states_lost = 0;
  uint64_t longest_loss = 0;
  double wall_s = 0;
  std::map<std::string, FailureGroup> failure_kinds;  // by failureKind(text)
};

struct SoakReport {
  SoakOptions options;
  std::array<KindFigures, kMotionKinds> kinds;
  KindFigures recovery;             // the slow moves back to a motion's start after a failure
  std::map<std::string, FailureGroup> recovery_refusals;  // of automaticErrorRecovery / setMotorPower
  long reconnects = 0;              // after the watchdog closed a session that hung
  uint64_t states_lost_idle = 0;    // lost between motions
  // The client's own counters (SessionTiming, summed over sessions): states received and the
  // message_id gaps it counted, and samples its ring could not take (0, or the figures above miss some).
  uint64_t client_states_received = 0;
  uint64_t client_states_missed = 0;
  uint64_t client_samples_dropped = 0;
  sim::ServerCounters simulator;    // what the simulator sent and lost
  std::string client_realtime;      // what the client's real-time thread got (SCHED_FIFO or not)
  std::string simulator_realtime;   // and the simulator's cycle thread (a controller never stalls)
  double wall_s = 0;
  long motions() const;
  long failures() const;
  long stallFailures() const;  // of the motions' failures, those after a stall
  long stalls = 0;             // failures whose message names a stall (motions and recovery moves)
};

// Runs the soak (blocking; minutes for hundreds of motions). `on_motion`, if set, is called on the
// calling thread after every motion and every recovery move. Throws std::runtime_error if the simulator or the first
// connection cannot start; failures of motions are counted, never thrown.
SoakReport runSoak(const SoakOptions& options, const std::function<void(const MotionResult&)>& on_motion = {});

// Whether a failure's message says a thread stalled longer than the controller tolerates -- the
// client's loop ("The client's real-time loop stalled for ...") or the simulator ("no state from the
// controller for ...") -- which on a virtual machine happens without any lost state.
bool isStallFailure(const std::string& text);

// The controller's error bits a message names ("kCommandJointVelocityLimitsViolation+..."), else its
// first 100 characters with each number as '#': the key that groups failures of one kind.
std::string failureKind(const std::string& text);

// The report as the table `rci-cli bench soak` prints, and as JSON (--json).
std::string reportText(const SoakReport& report);
std::string reportJson(const SoakReport& report);

}  // namespace rci_cli::soak
