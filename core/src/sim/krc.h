// SPDX-License-Identifier: Apache-2.0
// sim::Krc: the simulated KUKA controller (KR C4) running an RSI context -- the signal flow of its
// objects, the exchange's bookkeeping (IPOC, late answers, Delay, HOLDON, Timeout), the corrections
// and their clamps and monitors, and a position-controlled arm. No I/O: sim::KrcServer (krc_server.h)
// adds the socket and the clock, tests step it directly. docs/rsi.md, "The simulated KRC".
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "net/seqlock.h"
#include "rsi/config.h"
#include "rsi/link.h"

namespace xmate::sim {

// A context the simulated KRC cannot run (an unsupported object, a wiring cycle, a bad parameter, a
// model that is not a 6-axis arm). The text starts with FILE:LINE where there is one.
struct KrcError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct KrcConfig {
  std::string context_path;  // NAME.rsi.xml; its ETHERNET object's ConfigFile lies in the same folder
  std::string model = "kr6_r900_sixx";  // model::findRobotSpec name of a 6-axis arm
  rsi::CorrectionMode mode = rsi::CorrectionMode::kAbsolute;  // RSI_ON(#ABSOLUTE) or RSI_ON(#RELATIVE)
  int cycle_ms = 4;                                            // 4 (#IPO_FAST) or 12
  std::array<double, 6> start_deg{0, -90, 90, 0, 90, 0};       // A1..A6 where the KRL program's PTP left the arm
  uint64_t ipoc_start = 0;  // the first <Rob>'s IPOC; it then advances by cycle_ms per cycle (the controller clock)
  int restart_pause_ms = 2000;  // after RSI stopped on an error: pause, then RSI_ON again (0: no restart)
  double acceleration_per_speed = 5;  // axis acceleration limit, in units of its speed per second (full speed in 0.2 s)
  double torque_per_amp = 10;         // Nm of gear torque per A of motor current (DEF_MACur; an estimate)
  // One line per event (RSI on and off, RSITimeout, a clamp reached, a monitor tripped, a smartPAD
  // message). Called on the thread that runs the cycle; may be empty. Logging is the only thing a
  // cycle allocates for.
  std::function<void(const std::string&)> log;
};

enum class KrcState : uint8_t {
  kRunning,    // RSI on: a <Rob> every cycle, the arm follows the corrections
  kPaused,     // RSI stopped on an error; RSI_ON again when restart_pause_ms has passed
  kStopped,    // RSI stopped on an error, no restart (restart_pause_ms 0)
  kSuspended,  // RSI off on purpose (suspendSending): on again when the time has passed
};
const char* toString(KrcState state);  // any thread, real-time safe

// Why RSI stopped last (kNone while it never did).
enum class KrcStop : uint8_t { kNone, kTimeout, kAxisMonitor, kPosMonitor, kUnreachable, kSuspended };
const char* toString(KrcStop stop);  // any thread, real-time safe

// Everything observable, as one trivially copyable snapshot (published every cycle).
struct KrcStatus {
  KrcState state = KrcState::kRunning;
  KrcStop last_stop = KrcStop::kNone;
  uint32_t session = 0;        // 1 for the first RSI_ON, +1 for each restart
  uint64_t cycles = 0;         // controller cycles run (endCycle calls)
  uint64_t ipoc = 0;           // of the newest <Rob>
  uint64_t delay = 0;          // DEF_Delay: late answers in this session
  uint64_t late_in_a_row = 0;  // compared with the ETHERNET object's Timeout
  uint64_t robs_sent = 0;      // <Rob> datagrams made (duplicates not counted)
  uint64_t robs_duplicated = 0;
  uint64_t answers_used = 0;      // <Sen> that answered their <Rob> in time
  uint64_t answers_late = 0;      // cycles without an answer in time (all sessions)
  uint64_t answers_stale = 0;     // well-formed, but for another IPOC, a second one, or while RSI is off
  uint64_t answers_rejected = 0;  // not a readable <Sen> (the decoder's reason in lastReason())
  uint64_t answers_dropped = 0;   // discarded by the drop fault
  uint64_t answers_delayed = 0;   // counted late by the delay fault
  uint64_t timeouts = 0;          // RSITimeout stops
  std::array<double, 6> q_deg{};        // actual axes A1..A6 (DEF_AIPos)
  std::array<double, 6> q_set_deg{};    // set-point (DEF_ASPos): start + corrections, within the axis limits
  std::array<double, 6> dq_deg_s{};     // actual axis speeds
  std::array<double, 6> start_deg{};    // axes at this session's RSI_ON
  std::array<double, 6> axis_corr_deg{};  // total axis correction in effect (after AXISCORR's clamps)
  std::array<double, 6> pos_corr{};       // total Cartesian correction in effect: X Y Z mm, A B C deg
  std::array<double, 6> pose{};           // actual flange pose (DEF_RIst): X Y Z mm, A B C deg
  std::array<double, 6> pose_set{};       // set-point flange pose (DEF_RSol)
  std::array<double, 6> gear_torque{};    // Nm (GEARTORQUE)
  std::array<double, 6> motor_current{};  // A (DEF_MACur)
  std::array<double, 10> tech_t2{};       // DEF_Tech.T2 as the PC sent it (T21..T210)
  double override_pct = 100;
  uint64_t digin = 0;   // bit k-1 = input k
  uint64_t digout = 0;  // bit k-1 = output k (DIGOUT)
  int32_t program_status = 0;  // STATUS output 1 (docs/rsi.md)
  int32_t status_bits = 0;     // STATUS output 2
};

class Krc {
 public:
  // Reads the context and its Ethernet config, checks every object, orders the signal flow, loads
  // the model and switches RSI on at start_deg. Set-up (any thread; allocates). Throws
  // rsi::ConfigError (the files) or KrcError (what the simulated KRC cannot run), each saying
  // FILE:LINE, the object and what to do.
  explicit Krc(KrcConfig config);
  ~Krc();
  Krc(const Krc&) = delete;
  Krc& operator=(const Krc&) = delete;

  // ---- One cycle (one thread: the cycle thread or the test; allocation-free except for log lines)
  // Writes this cycle's <Rob> into out and returns its length; 0 while RSI is off (nothing to send).
  size_t beginCycle(char* out, size_t capacity);
  // True once per <Rob> the duplicate fault wants sent twice (ask after beginCycle).
  bool takeDuplicate();
  // A datagram that came in during this cycle. True if it is this cycle's answer and was taken.
  bool onAnswer(std::string_view datagram);
  bool answered() const { return answered_; }   // this cycle's answer is in
  bool awaitingAnswer() const;                   // a <Rob> went out and its answer is not in (ONLYSEND: never)
  // Ends the cycle: counts a missing answer late (HOLDON, Delay, Timeout), runs the signal flow,
  // moves the arm one cycle, counts restart pauses down. Call once per cycle, also while RSI is off.
  void endCycle();

  // ---- Scene and faults (any thread, real-time safe; applied from the next cycle on) ----------
  // The force the world applies to the arm at the flange: Fx Fy Fz (N), Tx Ty Tz (Nm), base frame.
  void setExternalWrench(const std::array<double, 6>& wrench) { wrench_.store(wrench); }
  void setDigitalInput(int index, bool level);  // index 1..64 (DIGIN's outputs); throws std::out_of_range
  void setOverride(double percent);              // 0..100 (OV_PRO's output); throws std::out_of_range
  void dropAnswers(int count) { drop_.store(count); }    // the next count answers are never received
  void delayAnswers(int count) { delay_.store(count); }  // the next count answers come after their cycle
  void duplicateRobs(int count) { duplicate_.store(count); }  // the next count <Rob> are sent twice
  void suspendSending(int ms);  // RSI off now (no timeout), on again (a new session) after ms

  // ---- Observation (any thread, lock-free) -----------------------------------------------------
  KrcStatus status() const;
  // The external wrench in the flange frame (what a sensor on the flange reads): N, Nm.
  std::array<double, 6> flangeWrench() const;
  const char* lastReason() const { return last_reason_.load(); }  // why the last <Sen> was refused

  // ---- Set-up facts (any thread) ------------------------------------------------------------------
  const rsi::Context& context() const;
  const rsi::EthernetConfig& ethernetConfig() const;
  int timeoutLimit() const;  // the ETHERNET object's Timeout
  int cycleMs() const;
  // The objects in the order the signal flow evaluates them (ETHERNET first: its outputs are sources).
  std::string evaluationOrder() const;
  // Output `index` (1-based) of object `object_id` after the last cycle; NaN if there is none.
  // For tests and tools: the thread that runs the cycles, or any thread while none runs (lock-step,
  // or the server stopped). Not real-time safe (looks the object up by name).
  double output(std::string_view object_id, int index) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  bool answered_ = false;
  std::atomic<int> drop_{0}, delay_{0}, duplicate_{0};
  std::atomic<const char*> last_reason_{""};
  net::Seqlock<std::array<double, 6>> wrench_;
};

}  // namespace xmate::sim
