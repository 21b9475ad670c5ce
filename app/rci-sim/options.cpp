// SPDX-License-Identifier: Apache-2.0
// Parsing and validation of rci-sim's command line (options.h), on CLI11.
#include "options.h"

#include <charconv>
#include <string_view>

#include <CLI/CLI.hpp>

#include "net/udp_socket.h"

namespace rcisim {
namespace {

std::string modelList() {
  std::string names;
  for (xmate::XmateType type : xmate::model::allRobotTypes()) {
    if (!names.empty()) names += ", ";
    names += xmate::model::robotSpec(type).name;
  }
  return names;
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
void describe(CLI::App& app, Options& o, std::string& model, long& control_port) {
  app.description(
      "Runs a simulated xMate controller that speaks the RCI protocol (TCP commands, 1 kHz UDP states).");
  app.footer("SIGINT or SIGTERM stops it cleanly. A wrong option exits with 2. See docs/simulator.md.");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.set_version_flag("--version", std::string("rci-sim ") + RCI_VERSION, "Print the version and exit");
  app.add_option("--model", model, "robot model: " + modelList() + " (default xmate7_pro)")
      ->type_name("NAME")
      ->check(modelName());
  app.add_option("--bind", o.bind_ip,
                 "address to listen on (default 127.0.0.1; anything else lets the whole network move the "
                 "simulated robot)")
      ->type_name("IP")
      ->check(ipv4Address());
  app.add_option("--port", o.port, "TCP command port (default 1337; 0 picks a free port)")
      ->type_name("P")
      ->check(wholeNumber(0, 65535));
  app.add_flag("--print-port", o.print_port, "print the bound TCP port alone on the first line of stdout");
  app.add_flag("--lockstep", o.lockstep, "lock-step clock: during motion each cycle waits for the client's answer");
  app.add_option("--lockstep-timeout", o.lockstep_timeout_ms,
                 "wall time before an unanswered cycle counts as lost (default 200)")
      ->type_name("MS")
      ->check(wholeNumber(1, 60000));
  app.add_option("--control-port", control_port,
                 "serve the control port (scene events, packet faults; 0 = free port)")
      ->type_name("P")
      ->check(wholeNumber(0, 65535));
  app.add_option_function<long>(
         "--ft-sensor", [&o](long port) { o.ft_sensor_port = uint16_t(port); },
         "also serve a simulated ATI Net F/T sensor (RDT over UDP) on this port of --bind, reading a zero "
         "wrench (0 = free port; a real sensor uses 49152)")
      ->type_name("P")
      ->check(wholeNumber(0, 65535));
  app.add_option("--control-bind", o.control_bind_ip, "address of the control port (default 127.0.0.1)")
      ->type_name("IP")
      ->check(ipv4Address());
  app.add_flag("--loopback-io", o.loopback_io, "wire DO k to DI k");
  app.add_flag("--motors-on", o.motors_on, "start with the motors powered on");
  app.add_option("--reboot-pause", o.reboot_pause_ms, "how long a reboot takes (default 2000)")
      ->type_name("MS")
      ->check(wholeNumber(0, 600000));
  app.add_option("--connect-timeout", o.connect_timeout_ms,
                 "a connection that has not sent Connect by then is closed (default 3000; 0 = never)")
      ->type_name("MS")
      ->check(wholeNumber(0, 3600000));
  app.add_option("--idle-timeout", o.idle_timeout_ms,
                 "a session silent this long gives way to a new client (default 10000; 0 = never)")
      ->type_name("MS")
      ->check(wholeNumber(0, 3600000));
  app.add_flag_callback("--no-realtime", [&o] { o.realtime = false; }, "do not ask for SCHED_FIFO and memory locking");
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
  CLI::App app("", "rci-sim");
  describe(app, o, model, control_port);
  return app.help();
}

bool isLoopbackAddress(const std::string& ip) { return ip == "localhost" || ip.rfind("127.", 0) == 0; }

Options parseOptions(int argc, const char* const* argv) {
  Options o;
  std::string model = "xmate7_pro";
  long control_port = -1;  // -1: no control port
  CLI::App app("", "rci-sim");
  describe(app, o, model, control_port);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    o.help = true;
  } catch (const CLI::CallForVersion&) {
    o.version = true;
  } catch (const CLI::ParseError& e) {
    throw UsageError(explain(e));
  }
  o.model = xmate::model::findRobotSpec(model);
  if (control_port >= 0) o.control_port = uint16_t(control_port);
  return o;
}

}  // namespace rcisim
