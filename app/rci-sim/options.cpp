// SPDX-License-Identifier: Apache-2.0
// Parsing and validation of rci-sim's command line (options.h), on CLI11.
#include "options.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "net/host_port.h"
#include "net/udp_socket.h"

namespace rcisim {
namespace {

std::string modelList() {
  std::string names;
  for (const xmate::model::RobotSpec& spec : xmate::model::allRobotSpecs()) {
    if (!names.empty()) names += ", ";
    names += spec.name;
  }
  return names;
}

// The text of the --rsi options that need checking after the parse.
struct RsiText {
  std::string target, mode = "absolute", start_joints, wrench;
  long cycle_ms = 4;
};

// "a,b,c,..." -> exactly N finite numbers; throws UsageError naming the option.
template <size_t N>
std::array<double, N> numberList(const std::string& option, const std::string& text, const char* what) {
  std::array<double, N> out{};
  size_t at = 0;
  for (size_t i = 0; i < N; ++i) {
    const size_t comma = i + 1 < N ? text.find(',', at) : text.size();
    double v = 0;
    const char* begin = text.data() + at;
    const char* end = text.data() + (comma == std::string::npos ? text.size() : comma);
    const auto [ptr, ec] = std::from_chars(begin, end, v);
    if (comma == std::string::npos || ec != std::errc() || ptr != end || !std::isfinite(v))
      throw UsageError(option + " takes " + std::to_string(N) + " numbers separated by commas (" + what + "), got '" +
                       text + "'");
    out[i] = v;
    at = comma + 1;
  }
  return out;
}

// CLI11 prefixes a validator's message with the option's name ("--port: takes ..."); describe()
// joins them into "--port takes ...".
CLI::Validator wholeNumber(long min, long max) {
  return CLI::Validator(
      [min, max](std::string& text) {
        long value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc() && end == text.data() + text.size() && value >= min && value <= max) return std::string();
        return "takes a whole number from " + std::to_string(min) + " to " + std::to_string(max) + ", got '" + text + "'";
      },
      "");
}

// A whole-number option from `min` to `max`, shown in the help as `type` ("N", "MS", "P").
template <class T>
CLI::Option* addWhole(CLI::App& app, const std::string& name, T& value, const std::string& help, const char* type,
                      long min, long max) {
  return app.add_option(name, value, help)->type_name(type)->check(wholeNumber(min, max));
}

// One of a few words; the message lists them ("takes absolute or relative, got 'x'").
CLI::Validator oneOf(std::vector<std::string> words, const std::string& listed) {
  return CLI::Validator(
      [words, listed](std::string& text) {
        for (const std::string& w : words)
          if (text == w) return std::string();
        return "takes " + listed + ", got '" + text + "'";
      },
      "");
}

CLI::Validator ipv4Address() {
  return CLI::Validator(
      [](std::string& text) {
        try {
          xmate::net::makeEndpoint(text, 0);
          return std::string();
        } catch (const std::invalid_argument&) {
          return "takes an IPv4 address such as 127.0.0.1, got '" + text + "'";
        }
      },
      "");
}

CLI::Validator modelName() {
  return CLI::Validator(
      [](std::string& text) {
        if (xmate::model::findRobotSpec(text)) return std::string();
        return "unknown model '" + text + "'; choose one of: " + modelList();
      },
      "");
}

// The command line, bound to `o`, `model` (the name given to --model) and `control_port` (-1 if
// not given).
void describe(CLI::App& app, Options& o, std::string& model, long& control_port, RsiText& rsi) {
  app.description(
      "Runs a simulated xMate controller that speaks the RCI protocol (TCP commands, 1 kHz UDP states), or with "
      "--rsi a simulated KUKA controller that runs an RSI context and exchanges RSI datagrams with a PC.");
  app.footer("SIGINT or SIGTERM stops it cleanly. A wrong option exits with 2. See docs/simulator.md and, for --rsi, "
             "docs/rsi.md.");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.set_version_flag("--version", std::string("rci-sim ") + RCI_VERSION, "Print the version and exit");
  app.add_option("--model", model, "robot model: " + modelList() + " (default xmate7_pro; kr6_r900_sixx with --rsi)")
      ->type_name("NAME")
      ->check(modelName());
  app.add_option("--bind", o.bind_ip,
                 "address to listen on (default 127.0.0.1; anything else lets the whole network move the "
                 "simulated robot)")
      ->type_name("IP")
      ->check(ipv4Address());
  addWhole(app, "--port", o.port, "TCP command port (default 1337; 0 picks a free port)", "P", 0, 65535);
  app.add_flag("--print-port", o.print_port, "print the bound TCP port alone on the first line of stdout");
  app.add_flag("--lockstep", o.lockstep,
               "lock-step clock: during motion each cycle waits for the client's answer (with --rsi: every cycle "
               "waits for the PC's <Sen>, and the next follows at once)");
  addWhole(app, "--lockstep-timeout", o.lockstep_timeout_ms,
           "wall time before an unanswered cycle counts as lost (default 200)",
           "MS", 1, 60000);
  addWhole(app, "--control-port", control_port,
           "serve the control port (scene events, packet faults; 0 = free port); with --rsi the simulated "
           "KRC's (push, DIGIN, override, answer faults, RSI off)",
           "P", 0, 65535);
  app.add_option_function<long>(
         "--ft-sensor", [&o](long port) { o.ft_sensor_port = uint16_t(port); },
         "also serve a simulated ATI Net F/T sensor (RDT over UDP) on this port of --bind, reading a zero "
         "wrench -- with --rsi the arm's external wrench in the flange frame (0 = free port; a real sensor uses 49152)")
      ->type_name("P")
      ->check(wholeNumber(0, 65535));
  app.add_option("--control-bind", o.control_bind_ip, "address of the control port (default 127.0.0.1)")
      ->type_name("IP")
      ->check(ipv4Address());
  app.add_flag("--loopback-io", o.loopback_io, "wire DO k to DI k");
  app.add_flag("--motors-on", o.motors_on, "start with the motors powered on");
  addWhole(app, "--reboot-pause", o.reboot_pause_ms, "how long a reboot takes (default 2000)", "MS", 0, 600000);
  addWhole(app, "--connect-timeout", o.connect_timeout_ms,
           "a connection that has not sent Connect by then is closed (default 3000; 0 = never)",
           "MS", 0, 3600000);
  addWhole(app, "--idle-timeout", o.idle_timeout_ms,
           "a session silent this long gives way to a new client (default 10000; 0 = never)",
           "MS", 0, 3600000);
  app.add_flag_callback("--no-realtime", [&o] { o.realtime = false; }, "do not ask for SCHED_FIFO and memory locking");

  // The simulated KUKA controller (docs/rsi.md, "The simulated KRC").
  app.add_option_function<std::string>(
         "--rsi", [&o](const std::string& path) { o.rsi_context = path; },
         "run a simulated KUKA controller (KRC) on this RSI context (NAME.rsi.xml; its ETHERNET object's ConfigFile "
         "lies next to it) instead of the xMate simulator")
      ->type_name("CONTEXT");
  app.add_option("--rsi-target", rsi.target,
                 "where the KRC sends its <Rob> datagrams: the PC (default: the Ethernet config's IP_NUMBER and PORT)")
      ->type_name("HOST:PORT");
  app.add_option("--rsi-mode", rsi.mode, "absolute or relative: how the KRL program starts RSI (default absolute)")
      ->type_name("MODE")
      ->check(oneOf({"absolute", "relative"}, "absolute or relative"));
  app.add_option("--cycle-ms", rsi.cycle_ms, "RSI cycle: 4 (#IPO_FAST, default) or 12")
      ->type_name("MS")
      ->check(oneOf({"4", "12"}, "4 (#IPO_FAST) or 12"));
  app.add_option("--start-joints-deg", rsi.start_joints,
                 "A1..A6 where RSI starts, degrees (default 0,-90,90,0,90,0)")
      ->type_name("A1,...,A6");
  addWhole(app, "--rsi-restart-pause", o.rsi_restart_pause_ms,
           "after RSI stops on an error (RSITimeout, a monitor), start it again after this long, like a looping "
           "KRL program (default 2000; 0 = never)",
           "MS", 0, 600000);
  app.add_option("--rsi-ipoc-start", o.rsi_ipoc_start, "the first IPOC (default 0; it advances by the cycle in ms)")
      ->type_name("N");
  app.add_option("--external-wrench", rsi.wrench,
                 "force and torque the world applies at the flange, base frame (N, Nm); the --ft-sensor reads it")
      ->type_name("FX,FY,FZ,TX,TY,TZ");
  addWhole(app, "--rsi-drop-answers", o.rsi_drop_answers,
           "fault: treat this many answers as never received",
           "N", 0, 1000000);
  addWhole(app, "--rsi-delay-answers", o.rsi_delay_answers, "fault: count this many answers late", "N", 0, 1000000);
  addWhole(app, "--rsi-duplicate", o.rsi_duplicate_robs,
           "fault: send this many <Rob> datagrams twice",
           "N", 0, 1000000);
  addWhole(app, "--rsi-suspend", o.rsi_suspend_ms,
           "fault: stop sending for this long (RSI off, no timeout)",
           "MS", 0, 600000);
  addWhole(app, "--rsi-faults-after", o.rsi_faults_after_ms,
           "when the faults above begin (default 1000 after the start)",
           "MS", 0, 3600000);
}

// CLI11's parse error as the message that main() prints: what was wrong with which option.
std::string explain(const CLI::ParseError& e) {
  const std::string what = e.what();
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    const auto colon = what.find(": ");
    std::string first = colon == std::string::npos ? what : what.substr(colon + 2);
    first = first.substr(0, first.find(' '));
    if (!first.empty() && first[0] == '-') return "unknown option '" + first + "'";
    return "unexpected argument '" + first + "' (rci-sim takes options only)";
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) return what.substr(0, what.find(':')) + " needs a value";
  if (dynamic_cast<const CLI::ValidationError*>(&e)) {
    const auto colon = what.find(": ");
    if (colon != std::string::npos && what.compare(colon + 2, 6, "takes ") == 0)
      return what.substr(0, colon) + " " + what.substr(colon + 2);  // "--port takes a whole number ..."
    if (colon != std::string::npos) return what.substr(colon + 2);  // "unknown model 'x'; choose one of ..."
  }
  return what;
}

}  // namespace

std::string usageText() {
  Options o;
  std::string model;
  long control_port = -1;
  RsiText rsi;
  CLI::App app("", "rci-sim");
  describe(app, o, model, control_port, rsi);
  return app.help();
}

void parseHostPort(const std::string& option, const std::string& text, std::string& host, uint16_t& port) {
  xmate::net::HostPort address;
  if (xmate::net::splitHostPort(text, 0, address) != xmate::net::HostPortProblem::kNone)
    throw UsageError(option + " takes HOST:PORT with a port from 1 to 65535, e.g. 127.0.0.1:49152, got '" + text + "'");
  try {
    xmate::net::makeEndpoint(address.host, address.port);
  } catch (const std::invalid_argument&) {
    throw UsageError(option + " takes an IPv4 address such as 127.0.0.1 before the port, got '" + address.host + "'");
  }
  host = address.host;
  port = address.port;
}

bool isLoopbackAddress(const std::string& ip) { return ip == "localhost" || ip.rfind("127.", 0) == 0; }

Options parseOptions(int argc, const char* const* argv) {
  Options o;
  std::string model = "xmate7_pro";
  long control_port = -1;  // -1: no control port
  RsiText rsi;
  CLI::App app("", "rci-sim");
  describe(app, o, model, control_port, rsi);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    o.help = true;
  } catch (const CLI::CallForVersion&) {
    o.version = true;
  } catch (const CLI::ParseError& e) {
    throw UsageError(explain(e));
  }
  if (control_port >= 0) o.control_port = uint16_t(control_port);
  if (o.help || o.version) return o;
  const bool model_given = app.count("--model") > 0;
  if (o.rsi_context) {
    if (!model_given) model = "kr6_r900_sixx";
    if (!rsi.target.empty()) parseHostPort("--rsi-target", rsi.target, o.rsi_target_ip, o.rsi_target_port);
    o.rsi_relative = rsi.mode == "relative";
    o.cycle_ms = int(rsi.cycle_ms);
    if (!rsi.start_joints.empty())
      o.start_joints_deg = numberList<6>("--start-joints-deg", rsi.start_joints, "A1 to A6 in degrees");
    if (!rsi.wrench.empty())
      o.external_wrench = numberList<6>("--external-wrench", rsi.wrench, "Fx Fy Fz in N, Tx Ty Tz in Nm");
  } else {
    for (const char* option : {"--rsi-target", "--rsi-mode", "--cycle-ms", "--start-joints-deg", "--rsi-restart-pause",
                               "--rsi-ipoc-start", "--external-wrench", "--rsi-drop-answers", "--rsi-delay-answers",
                               "--rsi-duplicate", "--rsi-suspend", "--rsi-faults-after"})
      if (app.count(option) > 0) throw UsageError(std::string(option) + " needs --rsi CONTEXT.rsi.xml");
  }
  o.model = xmate::model::findRobotSpec(model);
  if (!o.model) throw UsageError("unknown model '" + model + "'; choose one of: " + modelList());
  if (!o.rsi_context && o.model->family != xmate::model::RobotFamily::kXmate)
    throw UsageError("--model " + model + " is a KUKA arm: it runs over RSI; give --rsi CONTEXT.rsi.xml");
  return o;
}

}  // namespace rcisim
