// SPDX-License-Identifier: Apache-2.0
// rci-cli state --robot rsi:ETHERNET.xml: a KUKA arm's live values over RSI. An rsi::Link answers
// every <Rob> with zero corrections (the robot holds still); one line per cycle: IPOC, cycle time,
// axes, pose, motor currents and Delay -- those of them the Ethernet config sends.
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.h"
#include "model/robot_spec.h"
#include "net/clock.h"
#include "net/spsc_ring.h"
#include "net/udp_socket.h"
#include "rsi/config.h"
#include "rsi/link.h"

namespace rci_cli {
namespace {

using namespace xmate;

// The values a line shows, in columns, by the datagram element that carries them.
struct Group {
  const char* element;           // in the <Rob> datagram
  const char* tag;               // in the Ethernet config
  std::vector<const char*> attributes;
  const char* header;
  const char* format;            // of one value
  const char* what;              // for "not in this config"
};

const std::array<Group, 5> kGroups{{
    {"AIPos", "DEF_AIPos", {"A1", "A2", "A3", "A4", "A5", "A6"}, "A1 A2 A3 A4 A5 A6 [deg]", " %9.4f", "axes"},
    {"RIst", "DEF_RIst", {"X", "Y", "Z"}, "X Y Z [mm]", " %9.3f", "the pose"},
    {"RIst", "DEF_RIst", {"A", "B", "C"}, "A B C [deg]", " %8.3f", "the pose"},
    {"MACur", "DEF_MACur", {"A1", "A2", "A3", "A4", "A5", "A6"}, "MACur A1..A6", " %7.3f", "motor currents"},
    {"Delay", "DEF_Delay", {"D"}, "Delay", " %5.0f", "late answers counted by the robot"},
}};
constexpr size_t kMaxValues = 6 + 3 + 3 + 6 + 1;

// One received cycle, handed from the link's thread to this one (fixed size, no allocation).
struct Cycle {
  uint64_t ipoc = 0;
  int64_t received_ns = 0;
  uint32_t session = 0;
  std::array<double, kMaxValues> values{};
};
using CycleRing = net::SpscRing<Cycle, 4096>;  // 16 s at 4 ms: room for a terminal that lags

std::atomic<bool> g_interrupted{false};
void onStopSignal(int) { g_interrupted.store(true); }  // SIGINT, SIGTERM

std::string displayName(const std::string& model) {
  if (const auto* spec = model::findRobotSpec(model)) return std::string(spec->display_name) + " (" + model + ")";
  return model;
}

// The zero correction for what the config lets the PC correct: axes (AK), Cartesian (RK), or nothing.
// Zero is "hold still" in both modes: #ABSOLUTE takes it as the total since RSI_ON, #RELATIVE as the
// change since the last cycle.
rsi::Correction zeroCorrection(const rsi::EthernetConfig& config, std::string& what) {
  bool axis = false, cartesian = false;
  for (const rsi::Channel& c : config.receive) {
    axis = axis || c.element == "AK";
    cartesian = cartesian || c.element == "RK";
  }
  rsi::Correction zero;
  if (axis) {
    zero.kind = rsi::Correction::Kind::kAxis;
    what = "zero axis corrections (AK)";
  } else if (cartesian) {
    zero.kind = rsi::Correction::Kind::kCartesian;
    what = "zero Cartesian corrections (RK)";
  } else {
    what = "its RECEIVE elements at zero (it has no AK or RK correction)";
  }
  return zero;
}

// --port 0: a port no other program uses now, for tests and simulated robots (announced below).
std::string fileName(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int runStateRsi(const StateOptions& o) {
  const rsi::EthernetConfig config = rsi::readEthernetConfig(o.robot.rsi_config);  // "FILE:LINE: what" on errors
  const std::string ip = !o.listen.bind_ip.empty() ? o.listen.bind_ip : config.ip_is_placeholder ? "0.0.0.0" : config.ip;
  rsi::LinkOptions options;
  options.bind_ip = ip;
  options.port = int(o.listen.port);  // -1: the config's PORT; 0: a free one (announced below)
  rsi::Link rsi_link(config, options);

  // Which values this config sends; the slots of those it does.
  std::array<int, kMaxValues> slots{};
  std::array<bool, kGroups.size()> present{};
  std::string missing;
  size_t k = 0;
  for (size_t g = 0; g < kGroups.size(); ++g) {
    present[g] = true;
    for (const char* attribute : kGroups[g].attributes) {
      slots[k] = rsi_link.slot(kGroups[g].element, attribute);
      present[g] = present[g] && slots[k] >= 0;
      ++k;
    }
    const bool said = missing.find(kGroups[g].tag) != std::string::npos;
    if (!present[g] && !said)
      missing += std::string(missing.empty() ? "" : ", ") + kGroups[g].tag + " (" + kGroups[g].what + ")";
  }

  std::string answer_text;
  const rsi::Correction zero = zeroCorrection(config, answer_text);
  auto ring = std::make_unique<CycleRing>();
  CycleRing* cycles = ring.get();
  rsi_link.setCallback([&rsi_link, cycles, slots, zero](const rsi::RobDecoder& rob) {
    rsi::RobSample sample;  // this very <Rob>: the link publishes it before it calls back
    rsi_link.latest(sample);
    Cycle c;
    c.ipoc = rob.ipoc();
    c.received_ns = sample.received_ns;
    c.session = sample.session;
    for (size_t i = 0; i < kMaxValues; ++i) c.values[i] = slots[i] >= 0 ? rob.value(slots[i]) : NAN;
    cycles->push(c);  // never blocks: a full ring drops the line, not the answer
    return zero;
  });
  rsi_link.start();

  std::printf("# %s over RSI, %s (Type %s)%s\n", displayName(o.model_name).c_str(), fileName(config.path).c_str(),
              config.sentype.c_str(),
              config.only_send ? "; ONLYSEND is TRUE: the robot expects no answers, none are sent"
                               : ("; every <Rob> is answered with " + answer_text + ": the robot holds still").c_str());
  if (!missing.empty()) std::printf("# not sent by this config, so not shown: %s\n", missing.c_str());
  std::printf("# waiting for the robot on %s:%u -- start the KRL program with RSI_ON (Ctrl-C stops; gives up after "
              "%ld s without a <Rob>)\n",
              ip.c_str(), unsigned(rsi_link.port()), o.wait_s);
  std::string header = "# IPOC  cycle[ms]";
  for (size_t g = 0; g < kGroups.size(); ++g)
    if (present[g]) header += std::string("  ") + kGroups[g].header;
  std::fflush(stdout);

  g_interrupted.store(false);
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
  const int64_t wait_ns = int64_t(o.wait_s) * 1'000'000'000;
  int64_t last_activity = net::monotonicNs();
  int64_t previous_ns = 0;
  uint32_t session = 0;
  uint64_t rejected_seen = 0;
  bool was_receiving = false;
  long printed = 0;
  int status = 0;
  std::string line;
  while ((o.count == 0 || printed < o.count) && !g_interrupted.load()) {
    Cycle c;
    if (cycles->pop(c)) {
      if (c.session != session) {
        session = c.session;
        previous_ns = 0;
        std::printf("# session %u: the robot sends (first IPOC %llu)\n%s\n", session, (unsigned long long)c.ipoc,
                    header.c_str());
      }
      char buf[64];
      line.clear();
      std::snprintf(buf, sizeof buf, "%llu  ", (unsigned long long)c.ipoc);
      line += buf;
      if (previous_ns == 0)
        std::snprintf(buf, sizeof buf, "%9s", "-");
      else
        std::snprintf(buf, sizeof buf, "%9.3f", double(c.received_ns - previous_ns) * 1e-6);
      line += buf;
      size_t i = 0;
      for (size_t g = 0; g < kGroups.size(); ++g) {
        if (present[g]) {
          line += " ";
          for (size_t a = 0; a < kGroups[g].attributes.size(); ++a) {
            std::snprintf(buf, sizeof buf, kGroups[g].format, c.values[i + a]);
            line += buf;
          }
        }
        i += kGroups[g].attributes.size();
      }
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
      previous_ns = c.received_ns;
      last_activity = net::monotonicNs();
      was_receiving = true;
      ++printed;
      continue;
    }
    const int64_t now = net::monotonicNs();
    const rsi::LinkCounters counters = rsi_link.counters();
    if (counters.rejected > rejected_seen) {
      if (rejected_seen < 5)
        std::printf("# refused a datagram, not answered: %s\n", rsi_link.lastReason());
      rejected_seen = counters.rejected;
      std::fflush(stdout);
    }
    if (was_receiving && !rsi_link.receiving() && cycles->size() == 0) {
      was_receiving = false;
      std::printf("# the robot stopped sending (RSI_OFF, the program stopped, or the cable); waiting for it again\n");
      std::fflush(stdout);
    }
    if (now - last_activity > wait_ns) {
      std::fprintf(stderr,
                   "rci-cli: %s from the robot on %s:%u for %ld s; check that the KRL program runs RSI_ON, that "
                   "IP_NUMBER and PORT in %s are this PC's address and port (or give --bind and --port), and that no "
                   "firewall blocks UDP port %u; --wait S waits longer\n",
                   printed == 0 ? "no <Rob>" : "no more <Rob>", ip.c_str(), unsigned(rsi_link.port()), o.wait_s,
                   config.path.c_str(), unsigned(rsi_link.port()));
      status = 1;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  rsi_link.stop();

  const rsi::LinkCounters n = rsi_link.counters();
  std::printf("# %llu received, %llu answered, %llu refused, %llu answered late, %llu session(s)",
              (unsigned long long)n.received, (unsigned long long)n.answered, (unsigned long long)n.rejected,
              (unsigned long long)n.late, (unsigned long long)n.sessions);
  if (cycles->dropped() > 0) std::printf(", %llu not shown (the output could not keep up)", (unsigned long long)cycles->dropped());
  std::printf("; link thread: %s\n", rsi_link.realtimeStatus().describe().c_str());
  std::fflush(stdout);
  return status;
}

}  // namespace rci_cli
