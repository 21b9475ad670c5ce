// SPDX-License-Identifier: Apache-2.0
// The control-port line protocol (server_control.h): parsing, the commands, and the TCP thread that
// serves them.
#include "sim/server_control.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "net/realtime.h"
#include "sim/control_lines.h"
#include "sim/server_faults.h"

namespace xmate::sim {
namespace {

constexpr size_t kMaxLineLength = 1024;
constexpr int kPollMs = 100;

using UsageError = ControlUsageError;

std::string bits(const std::array<bool, 6>& b) {
  std::string s;
  for (bool v : b) s += v ? '1' : '0';
  return s;
}

// "off" or "2%,pairs=30%,burst=5/10000ms,seed=7": the loss pattern as one status value.
std::string lossText(const StateLoss& loss) {
  if (!loss.active()) return "off";
  std::ostringstream o;
  o << loss.probability * 100 << "%,pairs=" << loss.pair_share * 100 << "%";
  if (loss.burst_states > 0) o << ",burst=" << loss.burst_states << "/" << loss.burst_every_ms << "ms";
  o << ",seed=" << loss.seed;
  return o.str();
}

const char* safetyStopName(int api_value) {
  switch (api_value) {
    case 2: return "estop";
    case 3: return "gstop";
    default: return "none";
  }
}

// ---- The commands ------------------------------------------------------------------------------------

std::string runWrench(Server& server, const Words& w) {
  const std::array<double, 6> wrench = parseWrench(w);
  server.setExternalWrench(wrench);
  return wrenchText(wrench, "at the TCP");
}

std::string runSwitch(const Words& w, const std::function<void(bool)>& apply, const char* name) {
  expectWords(w, 2);
  const bool on = parseOnOff(w[1]);
  apply(on);
  return std::string(name) + (on ? " on" : " off");
}

std::string runDigitalInput(Server& server, const Words& w) {
  expectWords(w, 3);
  const int index = parseInteger(w[1], "the input index", 0, 5);
  const bool level = parseInteger(w[2], "the level", 0, 1) == 1;
  server.setDigitalInput(index, level);
  return "di " + std::to_string(index) + " = " + (level ? "1" : "0");
}

// "drop states N" / "drop commands N"
std::string runDrop(Server& server, const Words& w) {
  expectWords(w, 3);
  const int n = parseInteger(w[2], "N", 1, kMaxFaultCount);
  if (w[1] == "states") {
    server.dropStates(n);
    return "dropping the next " + std::to_string(n) + " states";
  }
  if (w[1] == "commands") {
    server.dropCommands(n);
    return "dropping the next " + std::to_string(n) + " commands";
  }
  throw UsageError("expected 'states' or 'commands', got '" + std::string(w[1]) + "'");
}

std::string runDelay(Server& server, const Words& w) {
  expectWords(w, 4);
  if (w[1] != "commands") throw UsageError("only commands can be delayed, got '" + std::string(w[1]) + "'");
  const int n = parseInteger(w[2], "N", 1, kMaxFaultCount);
  const int ms = parseInteger(w[3], "MS", 0, kMaxFaultDelayMs);
  server.delayCommands(n, ms);
  return "delaying the next " + std::to_string(n) + " commands by " + std::to_string(ms) + " ms";
}

// "2%" or "2" -> 0.02; a percentage from 0 to max_percent, else ControlUsageError naming `what`.
double parsePercent(std::string_view word, const char* what, double max_percent) {
  const std::string_view number = word.ends_with('%') ? word.substr(0, word.size() - 1) : word;
  double value = -1;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (ec != std::errc() || end != number.data() + number.size() || !(value >= 0 && value <= max_percent))
    throw UsageError(std::string(what) + " must be a percentage from 0 to " + std::to_string(int(max_percent)) +
                     ", got '" + std::string(word) + "'");
  return value / 100;
}

// The clauses of "loss ..." after the word "loss": states P%, pairs S%, burst B every MS, seed N,
// each at most once, in any order; states or burst must be among them.
StateLoss parseStateLoss(const Words& w) {
  StateLoss loss;
  bool states = false, pairs = false, burst = false, seed = false;
  auto once = [](bool& given, std::string_view clause) {
    if (given) throw UsageError("'" + std::string(clause) + "' is given twice");
    given = true;
  };
  auto value = [&](size_t at, std::string_view clause, const char* takes) {
    if (at >= w.size()) throw UsageError("'" + std::string(clause) + "' needs " + takes);
    return w[at];
  };
  for (size_t i = 1; i < w.size();) {
    const std::string_view clause = w[i];
    if (clause == "states") {
      once(states, clause);
      loss.probability = parsePercent(value(i + 1, clause, "P%"), "P", kMaxLossProbability * 100);
      i += 2;
    } else if (clause == "pairs") {
      once(pairs, clause);
      loss.pair_share = parsePercent(value(i + 1, clause, "S%"), "S", 100);
      i += 2;
    } else if (clause == "burst") {
      once(burst, clause);
      loss.burst_states = parseInteger(value(i + 1, clause, "B every MS"), "B", 1, kMaxBurstStates);
      if (value(i + 2, clause, "B every MS") != "every")
        throw UsageError("expected 'every' after the burst's length, got '" + std::string(w[i + 2]) + "'");
      loss.burst_every_ms = parseInteger(value(i + 3, clause, "B every MS"), "MS", 1, kMaxBurstEveryMs);
      i += 4;
    } else if (clause == "seed") {
      once(seed, clause);
      loss.seed = uint32_t(parseInteger(value(i + 1, clause, "N"), "N", 0, std::numeric_limits<int>::max()));
      i += 2;
    } else {
      throw UsageError("expected states, pairs, burst or seed, got '" + std::string(clause) + "'");
    }
  }
  if (!states && !burst) throw UsageError("say which states to lose: 'states P%', 'burst B every MS' or both");
  return loss;
}

// "losing 2 % of the states at random, 30 % of the losses in pairs, and 5 states in a row every 10000 ms; seed 7"
std::string lossAnswer(const StateLoss& loss) {
  std::string answer;
  if (loss.probability > 0) {
    char text[120];
    std::snprintf(text, sizeof text, "losing %g %% of the states at random, %g %% of the losses in pairs",
                  loss.probability * 100, loss.pair_share * 100);
    answer = text;
  }
  if (loss.burst_states > 0)
    answer += (answer.empty() ? "losing " : ", and ") + std::to_string(loss.burst_states) + " states in a row every " +
              std::to_string(loss.burst_every_ms) + " ms";
  return answer + "; seed " + std::to_string(loss.seed);
}

// "loss states 2% pairs 30% burst 5 every 10000 seed 7" / "loss off"
std::string runLoss(Server& server, const Words& w) {
  if (w.size() == 2 && w[1] == "off") {
    server.setStateLoss({});
    return "state loss off (" + std::to_string(server.status().counters.states_lost) + " states lost so far)";
  }
  if (w.size() < 2) throw UsageError("expected 'off' or what to lose");
  const StateLoss loss = parseStateLoss(w);
  server.setStateLoss(loss);
  return lossAnswer(loss);
}

// "payload KG [CX CY CZ]" (a point mass) or "payload follow"
std::string runPayload(Server& server, const Words& w) {
  if (w.size() == 2 && w[1] == "follow") {
    server.followConfiguredLoad();
    return "payload follows the configured load (setLoad)";
  }
  if (w.size() != 2 && w.size() != 5) throw UsageError("expected 1 or 4 arguments, got " + std::to_string(w.size() - 1));
  const double mass = parseNumber(w[1], "KG");
  std::array<double, 3> center{};
  const char* names[3] = {"CX", "CY", "CZ"};
  for (size_t i = 0; i + 2 < w.size(); ++i) center[i] = parseNumber(w[i + 2], names[i]);
  server.setActualPayload(mass, center, {});
  char text[160];
  std::snprintf(text, sizeof text, "payload %g kg at %g %g %g m (flange frame, point mass)", mass, center[0],
                center[1], center[2]);
  return text;
}

std::string runStatus(Server& server, const Words& w) {
  expectWords(w, 1);
  return formatStatus(server.status());
}

std::string runKill(Server& server, const Words& w) {
  expectWords(w, 1);
  server.kill();
  return "killed: no state stream, TCP closed, connections refused until 'restart'";
}

std::string runRestart(Server& server, const Words& w) {
  expectWords(w, 1);
  server.stop();
  server.start();
  return "restarted: a fresh controller listens on port " + std::to_string(server.port());
}

std::string runHelp(Server&, const Words& w) {
  expectWords(w, 1);
  return controlHelp();
}

const std::vector<ControlCommand<Server>>& commands() {
  static const std::vector<ControlCommand<Server>> list = {
      {"wrench", "wrench FX FY FZ TX TY TZ (N, Nm; base frame, at the TCP)", runWrench},
      {"estop", "estop on|off",
       [](Server& s, const Words& w) { return runSwitch(w, [&](bool on) { s.setEmergencyStop(on); }, "estop"); }},
      {"gstop", "gstop on|off",
       [](Server& s, const Words& w) { return runSwitch(w, [&](bool on) { s.setGuardStop(on); }, "gstop"); }},
      {"di", "di INDEX(0-5) LEVEL(0|1)", runDigitalInput},
      {"loopback", "loopback on|off (DO k drives DI k)",
       [](Server& s, const Words& w) { return runSwitch(w, [&](bool on) { s.setDoToDiLoopback(on); }, "loopback"); }},
      {"payload", "payload KG [CX CY CZ] (what really hangs on the flange) | payload follow", runPayload},
      {"drop", "drop states N | drop commands N", runDrop},
      {"delay", "delay commands N MS", runDelay},
      {"reorder", "reorder states N (pairs are swapped)",
       [](Server& s, const Words& w) {
         return runCountFault(w, "states", "reordering", kMaxFaultCount, [&](int n) { s.reorderStates(n); });
       }},
      {"corrupt", "corrupt states N",
       [](Server& s, const Words& w) {
         return runCountFault(w, "states", "corrupting", kMaxFaultCount, [&](int n) { s.corruptStates(n); });
       }},
      {"badlength", "badlength states N",
       [](Server& s, const Words& w) {
         return runCountFault(w, "states", "shortening", kMaxFaultCount, [&](int n) { s.sendWrongLengthStates(n); });
       }},
      {"loss", "loss states P% [pairs S%] [burst B every MS] [seed N] (until loss off) | loss off", runLoss},
      {"status", "status", runStatus},
      {"kill", "kill", runKill},
      {"restart", "restart (power-cycles the controller after a kill)", runRestart},
      {"help", "help", runHelp},
  };
  return list;
}

}  // namespace

std::string controlHelp() { return commandsHelp(commands()); }

std::string executeControlLine(Server& server, std::string_view line) { return executeCommand(server, commands(), line); }

std::string formatStatus(const ServerStatus& st) {
  std::ostringstream o;
  const ServerCounters& c = st.counters;
  const PendingFaults& p = st.pending;
  o << "running=" << st.running << " killed=" << st.killed << " rebooting=" << st.rebooting
    << " session=" << st.session << " streaming=" << st.streaming << " port=" << st.port
    << " client=" << (st.client.empty() ? "-" : st.client)
    << " clock=" << (st.clock == ClockMode::kLockStep ? "lockstep" : "realtime") << " message_id=" << st.message_id
    << " motors=" << (st.sim.motors_on ? "on" : "off") << " safety_stop=" << safetyStopName(st.sim.safety_stop)
    << " dragging=" << st.sim.dragging << " motion=" << st.sim.motion_active << " do=" << bits(st.sim.digital_out)
    << " di=" << bits(st.sim.digital_in) << " payload=" << st.sim.actual_payload_mass
    << " payload_follows_load=" << st.sim.actual_payload_follows_load << " wrench=";
  for (size_t i = 0; i < 6; ++i) o << (i ? "," : "") << st.sim.external_wrench[i];
  o << " cycles=" << c.cycles << " states_sent=" << c.states_sent << " states_dropped=" << c.states_dropped
    << " states_reordered=" << c.states_reordered << " states_corrupted=" << c.states_corrupted
    << " states_wrong_length=" << c.states_wrong_length << " commands_received=" << c.commands_received
    << " commands_used=" << c.commands_used << " commands_stale=" << c.commands_stale
    << " commands_malformed=" << c.commands_malformed << " commands_lost=" << c.commands_lost
    << " commands_dropped=" << c.commands_dropped << " commands_delayed=" << c.commands_delayed
    << " sessions=" << c.sessions << " reboots=" << c.reboots << " clients_refused=" << c.clients_refused
    << " sessions_dropped=" << c.sessions_dropped << " pending_drop_states=" << p.drop_states
    << " pending_drop_commands=" << p.drop_commands << " pending_delay_commands=" << p.delay_commands
    << " pending_reorder_states=" << p.reorder_states << " pending_corrupt_states=" << p.corrupt_states
    << " pending_badlength_states=" << p.wrong_length_states << " states_lost=" << c.states_lost
    << " loss_singles=" << c.loss_singles << " loss_pairs=" << c.loss_pairs << " loss_bursts=" << c.loss_bursts
    << " loss=" << lossText(st.state_loss);
  return o.str();
}

// ---- ControlPort ---------------------------------------------------------------------------------------

ControlPort::ControlPort(Server& server, std::string bind_ip, uint16_t port)
    : ControlPort([&server](std::string_view line) { return executeControlLine(server, line); }, std::move(bind_ip),
                  port) {}

ControlPort::ControlPort(Execute execute, std::string bind_ip, uint16_t port)
    : execute_(std::move(execute)), bind_ip_(std::move(bind_ip)), port_(port) {}

ControlPort::~ControlPort() { stop(); }

void ControlPort::start() {
  try {
    listener_.listen(bind_ip_, port_);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("control port cannot start: ") + e.what());
  }
  port_ = listener_.localPort();
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
}

void ControlPort::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  listener_.close();
}

void ControlPort::run() {
  net::nameThisThread("rci-sim-control");
  while (!stopping_) {
    if (auto conn = listener_.accept(kPollMs)) serve(*conn);
  }
}

void ControlPort::serve(net::TcpConnection& conn) {
  std::string line;
  while (!stopping_) {
    char ch = 0;
    const net::IoResult r = conn.readExact(&ch, 1, kPollMs);
    if (r == net::IoResult::kTimeout) continue;
    if (r != net::IoResult::kOk) return;
    if (ch != '\n') {
      if (ch != '\r') line += ch;
      if (line.size() <= kMaxLineLength) continue;
      const std::string answer = "error line longer than " + std::to_string(kMaxLineLength) + " characters\n";
      conn.sendAll(answer.data(), answer.size(), 1000);
      return;
    }
    if (line == "quit" || line == "exit") return;
    const std::string answer = execute_(line) + "\n";
    line.clear();
    if (conn.sendAll(answer.data(), answer.size(), 1000) != net::IoResult::kOk) return;
  }
}

}  // namespace xmate::sim
