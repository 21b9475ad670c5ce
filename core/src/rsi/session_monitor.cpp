// SPDX-License-Identifier: Apache-2.0
// rsi::SessionMonitor (session_monitor.h): phase, cycle, Delay and answer times from LinkSamples.
#include "rsi/session_monitor.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace xmate::rsi {

SessionMonitor::SessionMonitor(const Link& link, const Context& context) : delay_slot_(link.slot("Delay", "D")) {
  if (const Object* ethernet = context.ethernet())
    now_.timeout = int(numberParameter(context, *ethernet, "Timeout", 100));
}

void SessionMonitor::add(const LinkSample& s) {
  if (!seen_ || s.session != now_.session) {  // a new RSI session starts from nothing
    const int timeout = now_.timeout;
    now_ = SessionStatus{};
    now_.timeout = timeout;
    now_.session = s.session;
    seen_ = true;
    answers_count_ = answers_next_ = 0;
  } else {
    const uint64_t step = s.ipoc - last_ipoc_;
    if (step == 4 || step == 12) now_.cycle_ms = int(step);
  }
  last_ipoc_ = s.ipoc;
  if (delay_slot_ >= 0 && size_t(delay_slot_) < s.count) {
    const double delay = s.values[size_t(delay_slot_)];
    now_.late_in_a_row = delay > now_.delay ? now_.late_in_a_row + 1 : 0;
    now_.delay = delay;
  }
  if (s.late) ++now_.late_answers;
  if (s.answer_ns >= 0) {
    answers_[answers_next_] = s.answer_ns;
    answers_next_ = (answers_next_ + 1) % answers_.size();
    answers_count_ = std::min(answers_count_ + 1, answers_.size());
  }
}

SessionStatus SessionMonitor::status(bool receiving) const {
  SessionStatus s = now_;
  if (!seen_) {
    s.phase = SessionPhase::kWaiting;
  } else if (receiving) {
    s.phase = SessionPhase::kRunning;
  } else {
    s.phase = SessionPhase::kStopped;
    // RSITimeout: the robot's count of late answers grew on (nearly) every cycle before it stopped.
    const int enough = std::max(1, std::min(s.timeout, 10));
    s.cause = s.late_in_a_row >= enough ? StopCause::kTimeout : StopCause::kByController;
  }
  if (answers_count_ > 0) {
    std::array<int32_t, 250> sorted = answers_;
    const size_t k = (answers_count_ * 99 + 99) / 100 - 1;  // the 99th percentile's rank
    std::nth_element(sorted.begin(), sorted.begin() + long(k), sorted.begin() + long(answers_count_));
    s.answer_p99_ms = sorted[k] * 1e-6;
  }
  return s;
}

std::string describe(const SessionStatus& s) {
  char text[320];
  switch (s.phase) {
    case SessionPhase::kWaiting:
      return "Waiting for the robot: start the KRL program with RSI_ON on the controller.";
    case SessionPhase::kRunning:
      std::snprintf(text, sizeof text, "RSI running, %d ms cycle; %g late answers counted by the robot",
                    s.cycle_ms > 0 ? s.cycle_ms : 4, s.delay);
      return text;
    case SessionPhase::kStopped:
      if (s.cause == StopCause::kTimeout) {
        std::snprintf(text, sizeof text,
                      "RSI stopped: the robot counted late answers until its limit of %d (RSITimeout). Check that "
                      "nothing else loads this PC or the network, then start the KRL program again.",
                      s.timeout);
        return text;
      }
      return "RSI stopped by the controller (RSI_OFF, the KRL program ended, a correction monitor or an error): "
             "see the controller's message window, then start the KRL program again.";
  }
  return {};
}

}  // namespace xmate::rsi
