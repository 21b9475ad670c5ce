// SPDX-License-Identifier: Apache-2.0
// The soak's report (soak.h): the table `rci-cli bench soak` prints, and the same figures as JSON.
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "soak/soak.h"

namespace rci_cli::soak {
namespace {

std::string format(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

std::string lossText(const SoakOptions& o) {
  if (o.loss_percent == 0 && o.burst_states == 0) return "nothing lost";
  std::string text = format("%g %% of the states lost at random (%g %% of the losses in pairs)", o.loss_percent,
                            o.pair_percent);
  if (o.burst_states > 0) text += format(" and %d in a row every %d ms", o.burst_states, o.burst_every_ms);
  return text + format(", seed %u", o.seed);
}

std::string setupText(const SoakOptions& o) {
  return format("%ld motions against the in-process simulator (%s), ", o.motions,
                o.lockstep ? "lock-step clock" : "real-time clock") +
         lossText(o) + (o.burners ? ", two CPU burners" : ", no CPU burners");
}

std::string rowText(const char* name, const KindFigures& k) {
  return format("  %-20s %6ld %7ld %7ld %12llu %13llu %9.1f\n", name, k.count, k.failures, k.stall_failures,
                static_cast<unsigned long long>(k.states_lost), static_cast<unsigned long long>(k.longest_loss),
                k.wall_s);
}

std::string failuresText(const char* name, const std::map<std::string, FailureGroup>& groups) {
  std::string text;
  for (const auto& [kind, group] : groups)
    text += format("  %s: %ld x ", name, group.count) + kind + "\n    first: " + group.example + "\n";
  return text;
}

std::string countersText(const SoakReport& r) {
  const sim::ServerCounters& s = r.simulator;
  return format("  the client counted %llu states missed of %llu received (ring overflows: %llu); the simulator "
                "lost %llu of %llu states: %llu single, %llu pairs, %llu bursts\n",
                static_cast<unsigned long long>(r.client_states_missed),
                static_cast<unsigned long long>(r.client_states_received),
                static_cast<unsigned long long>(r.client_samples_dropped), static_cast<unsigned long long>(s.states_lost),
                static_cast<unsigned long long>(s.states_sent + s.states_dropped),
                static_cast<unsigned long long>(s.loss_singles), static_cast<unsigned long long>(s.loss_pairs),
                static_cast<unsigned long long>(s.loss_bursts));
}

nlohmann::json failuresJson(const std::map<std::string, FailureGroup>& groups) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [kind, group] : groups) out.push_back({{"kind", kind}, {"count", group.count}, {"first", group.example}});
  return out;
}

nlohmann::json figuresJson(const KindFigures& k) {
  return {{"count", k.count},           {"failures", k.failures}, {"stall_failures", k.stall_failures},
          {"states_lost", k.states_lost}, {"longest_loss", k.longest_loss},
          {"wall_s", k.wall_s},         {"failure_kinds", failuresJson(k.failure_kinds)}};
}

}  // namespace

const char* kindName(MotionKind kind) {
  switch (kind) {
    case MotionKind::kMoveJ: return "MOVEJ";
    case MotionKind::kMoveL: return "MOVEL";
    case MotionKind::kMoveC: return "MOVEC";
    case MotionKind::kPath: return "PATH";
    case MotionKind::kCartesianCallback: return "cartesian callback";
    case MotionKind::kJointCallback: return "joint callback";
  }
  return "?";
}

std::string reportText(const SoakReport& r) {
  std::string text = "rci-cli bench soak: " + setupText(r.options) + "\n";
  text += "  client real-time thread: " + r.client_realtime + "\n";
  text += "  simulator cycle thread:  " + r.simulator_realtime + "\n\n";
  text += format("  %-20s %6s %7s %7s %12s %13s %9s\n", "motion", "count", "failed", "stalls", "states lost",
                 "longest loss", "wall s");
  for (size_t i = 0; i < kMotionKinds; ++i) text += rowText(kindName(MotionKind(i)), r.kinds[i]);
  text += rowText("recovery moves", r.recovery);
  text += format("  %-20s %6s %7s %7s %12llu\n", "between motions", "", "", "",
                 static_cast<unsigned long long>(r.states_lost_idle));
  text += format("  %-20s %6ld %7ld %7ld %12s %13s %9.1f\n", "all motions", r.motions(), r.failures(),
                 r.stallFailures(), "", "", r.wall_s);
  text += format("  (stalls: failures after the machine stalled a thread longer than the controller tolerates --\n"
                 "  %ld times -- lost states or not: the one naming the stall and those in its recovery)\n\n",
                 r.stalls);
  text += countersText(r);
  if (r.reconnects > 0) text += format("  reconnects after a motion hung: %ld\n", r.reconnects);
  if (r.failures() == 0 && r.recovery.failures == 0 && r.recovery_refusals.empty()) return text;
  text += "\nfailures (by kind: the error bits named, else the message's start):\n";
  for (size_t i = 0; i < kMotionKinds; ++i) text += failuresText(kindName(MotionKind(i)), r.kinds[i].failure_kinds);
  text += failuresText("recovery move", r.recovery.failure_kinds);
  text += failuresText("recovery refused", r.recovery_refusals);
  return text;
}

std::string reportJson(const SoakReport& r) {
  const SoakOptions& o = r.options;
  const sim::ServerCounters& s = r.simulator;
  nlohmann::json kinds = nlohmann::json::object();
  for (size_t i = 0; i < kMotionKinds; ++i) kinds[kindName(MotionKind(i))] = figuresJson(r.kinds[i]);
  const nlohmann::json out = {
      {"options",
       {{"motions", o.motions}, {"loss_percent", o.loss_percent}, {"pair_percent", o.pair_percent},
        {"burst_states", o.burst_states}, {"burst_every_ms", o.burst_every_ms}, {"seed", o.seed},
        {"burners", o.burners}, {"clock", o.lockstep ? "lockstep" : "realtime"}}},
      {"motions", r.motions()},
      {"failures", r.failures()},
      {"stall_failures", r.stallFailures()},
      {"stalls", r.stalls},
      {"kinds", kinds},
      {"recovery", figuresJson(r.recovery)},
      {"recovery_refusals", failuresJson(r.recovery_refusals)},
      {"reconnects", r.reconnects},
      {"states_lost_between_motions", r.states_lost_idle},
      {"client",
       {{"states_received", r.client_states_received}, {"states_missed", r.client_states_missed},
        {"samples_dropped", r.client_samples_dropped}, {"realtime", r.client_realtime}}},
      {"simulator",
       {{"states_sent", s.states_sent}, {"states_dropped", s.states_dropped}, {"states_lost", s.states_lost},
        {"loss_singles", s.loss_singles}, {"loss_pairs", s.loss_pairs}, {"loss_bursts", s.loss_bursts},
        {"commands_lost", s.commands_lost}, {"realtime", r.simulator_realtime}}},
      {"wall_s", r.wall_s},
  };
  return out.dump(2);
}

}  // namespace rci_cli::soak
