// SPDX-License-Identifier: Apache-2.0
// The simulated KRC's control port commands (krc_control.h).
#include "sim/krc_control.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include "sim/control_lines.h"
#include "sim/server_faults.h"

namespace xmate::sim {
namespace {

constexpr int kMaxCount = kMaxFaultCount;  // as the simulated xMate's faults
constexpr int kMaxSuspendMs = 600'000;

std::string runWrench(Krc& krc, const Words& w) {
  const std::array<double, 6> wrench = parseWrench(w);
  krc.setExternalWrench(wrench);
  return wrenchText(wrench, "at the flange");
}

std::string runDigitalInput(Krc& krc, const Words& w) {
  expectWords(w, 3);
  const int index = parseInteger(w[1], "the input index", 1, 64);
  const bool level = parseInteger(w[2], "the level", 0, 1) == 1;
  krc.setDigitalInput(index, level);
  return "di " + std::to_string(index) + " = " + (level ? "1" : "0");
}

std::string runOverride(Krc& krc, const Words& w) {
  expectWords(w, 2);
  const double percent = parseNumber(w[1], "the override");
  if (percent < 0 || percent > 100) throw ControlUsageError("the override must be from 0 to 100 %");
  krc.setOverride(percent);
  char text[64];
  std::snprintf(text, sizeof text, "override %g %%", percent);
  return text;
}

std::string runSuspend(Krc& krc, const Words& w) {
  expectWords(w, 2);
  const int ms = parseInteger(w[1], "MS", 1, kMaxSuspendMs);
  krc.suspendSending(ms);
  return "RSI off for " + std::to_string(ms) + " ms (no timeout), then a new session";
}

const std::vector<ControlCommand<Krc>>& commands() {
  static const std::vector<ControlCommand<Krc>> list = {
      {"wrench", "wrench FX FY FZ TX TY TZ (N, Nm; base frame, at the flange)", runWrench},
      {"di", "di INDEX(1-64) LEVEL(0|1)", runDigitalInput},
      {"override", "override PERCENT(0-100)", runOverride},
      {"drop", "drop answers N",
       [](Krc& k, const Words& w) {
         return runCountFault(w, "answers", "dropping", kMaxCount, [&](int n) { k.dropAnswers(n); });
       }},
      {"delay", "delay answers N (each counts late)",
       [](Krc& k, const Words& w) {
         return runCountFault(w, "answers", "delaying", kMaxCount, [&](int n) { k.delayAnswers(n); });
       }},
      {"duplicate", "duplicate robs N",
       [](Krc& k, const Words& w) {
         return runCountFault(w, "robs", "duplicating", kMaxCount, [&](int n) { k.duplicateRobs(n); });
       }},
      {"suspend", "suspend MS (RSI off without a timeout)", runSuspend},
      {"status", "status",
       [](Krc& k, const Words& w) {
         expectWords(w, 1);
         return formatKrcStatus(k.status());
       }},
      {"help", "help",
       [](Krc&, const Words& w) {
         expectWords(w, 1);
         return krcControlHelp();
       }},
  };
  return list;
}

template <size_t N>
void list(std::ostringstream& o, const std::array<double, N>& values) {
  for (size_t i = 0; i < N; ++i) o << (i ? "," : "") << values[i];
}

}  // namespace

std::string executeKrcControlLine(Krc& krc, std::string_view line) { return executeCommand(krc, commands(), line); }

std::string krcControlHelp() { return commandsHelp(commands()); }

std::string formatKrcStatus(const KrcStatus& s) {
  std::ostringstream o;
  o << "state=" << toString(s.state) << " last_stop=" << toString(s.last_stop) << " session=" << s.session
    << " cycles=" << s.cycles << " ipoc=" << s.ipoc << " delay=" << s.delay << " late_in_a_row=" << s.late_in_a_row
    << " robs_sent=" << s.robs_sent << " robs_duplicated=" << s.robs_duplicated << " answers_used=" << s.answers_used
    << " answers_late=" << s.answers_late << " answers_stale=" << s.answers_stale
    << " answers_rejected=" << s.answers_rejected << " answers_dropped=" << s.answers_dropped
    << " answers_delayed=" << s.answers_delayed << " timeouts=" << s.timeouts << " axes_deg=";
  list(o, s.q_deg);
  o << " axis_corr_deg=";
  list(o, s.axis_corr_deg);
  o << " pose=";
  list(o, s.pose);
  o << " gear_torque=";
  list(o, s.gear_torque);
  o << " override=" << s.override_pct << " digin=0x" << std::hex << s.digin << " digout=0x" << s.digout << std::dec
    << " program_status=" << s.program_status;
  return o.str();
}

}  // namespace xmate::sim
