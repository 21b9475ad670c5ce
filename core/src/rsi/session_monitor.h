// SPDX-License-Identifier: Apache-2.0
// rsi::SessionMonitor: what an RSI session is doing, from the link's samples -- waiting for the
// robot, running, or stopped and most likely why -- with the cycle, the robot's count of late
// answers (Delay) and the PC's answer time p99. For the window's status bar and rci-cli.
// docs/rsi.md, "Watching a session".
#pragma once

#include <array>
#include <cstdint>

#include "rsi/config.h"
#include "rsi/link.h"

namespace xmate::rsi {

enum class SessionPhase { kWaiting, kRunning, kStopped };
// Why the robot stopped sending, as far as the PC can tell.
enum class StopCause {
  kNone,         // not stopped
  kTimeout,      // the robot counted late answers up to the context's Timeout: RSITimeout
  kByController  // no late answers before it: RSI_OFF, the KRL program ended, a monitor or an error
};

struct SessionStatus {
  SessionPhase phase = SessionPhase::kWaiting;
  StopCause cause = StopCause::kNone;
  uint32_t session = 0;        // 1, 2, ...: the RSI session the samples are of
  int cycle_ms = 0;            // 4 or 12 from the IPOC's steps (a KRC's clock); 0 when not seen
  double delay = 0;            // the robot's DEF_Delay in its last <Rob> (late answers it counted)
  int late_in_a_row = 0;       // <Rob>s in a row, to the last, in which Delay grew
  int timeout = 100;           // the context's ETHERNET Timeout
  double answer_p99_ms = 0;    // the PC's answer time over the last 250 cycles (0: none yet)
  uint64_t late_answers = 0;   // answers the PC sent later than a cycle, this session
};

// Operator words for a status, e.g. "RSI stopped: the robot counted 100 late answers in a row
// (RSITimeout) -- start the KRL program again"; never an enum name.
std::string describe(const SessionStatus& status);

class SessionMonitor {
 public:
  // Set-up: the link's DEF_Delay slot and the context's ETHERNET Timeout.
  SessionMonitor(const Link& link, const Context& context);

  // The consumer thread of the link's samples, in order (allocation-free).
  void add(const LinkSample& sample);
  // The same thread: the status now; `receiving` is Link::receiving().
  SessionStatus status(bool receiving) const;

 private:
  int delay_slot_ = -1;
  SessionStatus now_;
  uint64_t last_ipoc_ = 0;
  bool seen_ = false;
  std::array<int32_t, 250> answers_{};  // ns, a ring of the last answer times
  size_t answers_count_ = 0, answers_next_ = 0;
};

}  // namespace xmate::rsi
