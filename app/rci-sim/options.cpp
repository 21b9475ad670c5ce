// SPDX-License-Identifier: Apache-2.0
// Parsing and validation of rci-sim's command line (options.h).
#include "options.h"

#include <charconv>
#include <string_view>

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

long parseNumber(std::string_view option, std::string_view text, long min, long max) {
  long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max)
    throw UsageError(std::string(option) + " takes a whole number from " + std::to_string(min) + " to " +
                     std::to_string(max) + ", got '" + std::string(text) + "'");
  return value;
}

std::string checkedAddress(std::string_view option, std::string_view text) {
  try {
    xmate::net::makeEndpoint(std::string(text), 0);
  } catch (const std::invalid_argument&) {
    throw UsageError(std::string(option) + " takes an IPv4 address such as 127.0.0.1, got '" + std::string(text) + "'");
  }
  return std::string(text);
}

}  // namespace

std::string usageText() {
  return "usage: rci-sim [options]\n"
         "Runs a simulated xMate controller that speaks the RCI protocol (TCP commands, 1 kHz UDP states).\n"
         "\n"
         "  --model NAME          robot model: " + modelList() + " (default xmate7_pro)\n"
         "  --bind IP             address to listen on (default 127.0.0.1; anything else lets the\n"
         "                        whole network move the simulated robot)\n"
         "  --port P              TCP command port (default 1337; 0 picks a free port)\n"
         "  --print-port          print the bound TCP port alone on the first line of stdout\n"
         "  --lockstep            lock-step clock: during motion each cycle waits for the client's answer\n"
         "  --lockstep-timeout MS wall time before an unanswered cycle counts as lost (default 200)\n"
         "  --control-port P      serve the control port (scene events, packet faults; 0 = free port)\n"
         "  --control-bind IP     address of the control port (default 127.0.0.1)\n"
         "  --loopback-io         wire DO k to DI k\n"
         "  --motors-on           start with the motors powered on\n"
         "  --reboot-pause MS     how long a reboot takes (default 2000)\n"
         "  --connect-timeout MS  a connection that has not sent Connect by then is closed (default 3000;\n"
         "                        0 = never)\n"
         "  --idle-timeout MS     a session silent this long gives way to a new client (default 10000;\n"
         "                        0 = never)\n"
         "  --no-realtime         do not ask for SCHED_FIFO and memory locking\n"
         "  --help                this text\n"
         "\n"
         "SIGINT or SIGTERM stops it cleanly. See docs/simulator.md.\n";
}

bool isLoopbackAddress(const std::string& ip) { return ip == "localhost" || ip.rfind("127.", 0) == 0; }

Options parseOptions(int argc, const char* const* argv) {
  Options o;
  o.model = xmate::model::findRobotSpec("xmate7_pro");
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&]() -> std::string_view {
      if (i + 1 >= argc) throw UsageError(std::string(arg) + " needs a value");
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      o.help = true;
    } else if (arg == "--model") {
      const std::string_view name = value();
      o.model = xmate::model::findRobotSpec(name);
      if (!o.model) throw UsageError("unknown model '" + std::string(name) + "'; choose one of: " + modelList());
    } else if (arg == "--bind") {
      o.bind_ip = checkedAddress(arg, value());
    } else if (arg == "--port") {
      o.port = uint16_t(parseNumber(arg, value(), 0, 65535));
    } else if (arg == "--print-port") {
      o.print_port = true;
    } else if (arg == "--lockstep") {
      o.lockstep = true;
    } else if (arg == "--lockstep-timeout") {
      o.lockstep_timeout_ms = int(parseNumber(arg, value(), 1, 60000));
    } else if (arg == "--control-port") {
      o.control_port = uint16_t(parseNumber(arg, value(), 0, 65535));
    } else if (arg == "--control-bind") {
      o.control_bind_ip = checkedAddress(arg, value());
    } else if (arg == "--loopback-io") {
      o.loopback_io = true;
    } else if (arg == "--motors-on") {
      o.motors_on = true;
    } else if (arg == "--reboot-pause") {
      o.reboot_pause_ms = int(parseNumber(arg, value(), 0, 600000));
    } else if (arg == "--connect-timeout") {
      o.connect_timeout_ms = int(parseNumber(arg, value(), 0, 3600000));
    } else if (arg == "--idle-timeout") {
      o.idle_timeout_ms = int(parseNumber(arg, value(), 0, 3600000));
    } else if (arg == "--no-realtime") {
      o.realtime = false;
    } else {
      throw UsageError("unknown option '" + std::string(arg) + "'");
    }
  }
  return o;
}

}  // namespace rcisim
