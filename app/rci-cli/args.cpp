// SPDX-License-Identifier: Apache-2.0
// The command-line helpers of rci-cli (cli.h): --robot, --model and whole-number options on CLI11,
// with validators whose messages say what the option takes and what it got.
#include <charconv>

#include <CLI/CLI.hpp>

#include "cli.h"
#include "model/robot_spec.h"
#include "net/host_port.h"
#include "net/udp_socket.h"

namespace rci_cli {
namespace {

// "xmate3_pro, xmate7_pro, ..." or "kr6_r900_sixx, kr16_2": the models of one family, for messages.
std::string modelNames(xmate::model::RobotFamily family) {
  std::string names;
  for (const xmate::model::RobotSpec& spec : xmate::model::allRobotSpecs())
    if (spec.family == family) names += (names.empty() ? "" : ", ") + std::string(spec.name);
  return names;
}
std::string xmateModels() { return modelNames(xmate::model::RobotFamily::kXmate); }
std::string kukaModels() { return modelNames(xmate::model::RobotFamily::kKuka); }

// A whole number in [lo, hi], or why not ("" if it is one).
std::string wholeNumberProblem(const std::string& text, long lo, long hi) {
  long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc() && end == text.data() + text.size() && v >= lo && v <= hi) return {};
  return "takes a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got '" + text + "'";
}

// A check that runs `parse` on the value and reports the UsageError it throws (the parser's own
// words), so the check and the parse cannot disagree.
template <class Parse>
CLI::Validator parsedBy(Parse parse) {
  return CLI::Validator(
      [parse](std::string& text) {
        try {
          parse(text);
          return std::string();
        } catch (const UsageError& e) {
          return std::string(e.what());
        }
      },
      "");
}

// CLI11 prefixes a validator's message with the option's name: "--cycles: takes ..."; main() joins
// them into "--cycles takes ...".
CLI::Validator wholeNumber(long lo, long hi) {
  return CLI::Validator([lo, hi](std::string& text) { return wholeNumberProblem(text, lo, hi); }, "");
}

}  // namespace

CLI::Option* addDecimalOption(CLI::App& command, const std::string& name, double& value, double lo, double hi,
                              const std::string& meaning, const std::string& help) {
  return command.add_option(name, value, help)->check(CLI::Validator(
      [lo, hi, meaning](std::string& text) {
        try {
          size_t end = 0;
          const double v = std::stod(text, &end);
          if (end == text.size() && v >= lo && v <= hi) return std::string();
        } catch (const std::exception&) {
        }
        return "takes " + meaning + ", got '" + text + "'";
      },
      ""));
}

// "HOST" or "HOST:PORT" (default_port when left out); UsageError ending in `expected` otherwise.
HostPort parseHostPort(const std::string& text, uint16_t default_port, const std::string& expected) {
  xmate::net::HostPort split;
  switch (xmate::net::splitHostPort(text, default_port, split)) {
    case xmate::net::HostPortProblem::kNone: return {split.host, split.port};
    case xmate::net::HostPortProblem::kNoHost:
    case xmate::net::HostPortProblem::kNoPort: throw UsageError("'" + text + "': no host; " + expected);
    case xmate::net::HostPortProblem::kBadPort: break;
  }
  throw UsageError("'" + text + "': the port must be a whole number from 1 to 65535, got '" + split.port_text + "'; " +
                   expected);
}

RobotTarget parseRobotTarget(const std::string& text, bool sim_allowed, bool rsi_allowed) {
  std::string expected = sim_allowed ? "write sim (the in-process simulator) or HOST:PORT, e.g. 127.0.0.1:1337"
                                     : "write HOST:PORT, e.g. 127.0.0.1:1337";
  if (rsi_allowed)
    expected += sim_allowed ? "; for a KUKA rsi:ETHERNET.xml (its RSI Ethernet config) or rsi-sim (a simulated KRC)"
                            : "; for a KUKA rsi:ETHERNET.xml (its RSI Ethernet config)";
  RobotTarget target;
  if (text == "sim") {
    if (!sim_allowed) throw UsageError("'sim': this command needs a controller address; " + expected);
    target.in_process = true;
    return target;
  }
  if (text == "rsi-sim" || text.rfind("rsi:", 0) == 0) {
    if (!rsi_allowed) throw UsageError("'" + text + "': this command drives xMate robots only; " + expected);
    if (text == "rsi-sim" && !sim_allowed) throw UsageError("'rsi-sim': this command needs a robot; " + expected);
    if (text == "rsi:")
      throw UsageError("'rsi:': no file; write rsi:ETHERNET.xml, the robot's RSI Ethernet config (e.g. "
                       "rsi:RSI_EthernetConfig.xml)");
    target.rsi = true;
    if (text != "rsi-sim") target.rsi_config = text.substr(4);
    return target;
  }
  target.address = parseHostPort(text, target.address.port, expected);
  return target;
}

void parseSensorAddress(const std::string& text, FtOptions& options) {
  const HostPort address = parseHostPort(text, 49152, "write the sensor's HOST or HOST:PORT, e.g. 192.168.1.1");
  options.host = address.host;
  options.port = address.port;
}

CLI::Option* addSensorOption(CLI::App& command, FtOptions& options) {
  CLI::Option* option = command.add_option_function<std::string>(
      "--sensor", [&options](const std::string& text) { parseSensorAddress(text, options); },
      "the sensor's address, HOST or HOST:PORT (port 49152 if left out)");
  option->type_name("HOST[:PORT]");
  option->check(parsedBy([](const std::string& text) {
    FtOptions unused;
    parseSensorAddress(text, unused);
  }));
  return option;
}

xmate::XmateType parseModel(const std::string& text) {
  if (isRsiModel(text))
    throw UsageError("'" + text + "' is a KUKA arm; this takes an xMate model: " + xmateModels() +
                     " (KUKA arms: state --robot rsi:ETHERNET.xml --model " + text + ")");
  if (const auto* spec = xmate::model::findXmateSpec(text)) return spec->type;
  throw UsageError("unknown model '" + text + "'; choose one of: " + xmateModels());
}

std::string unknownModelText(const std::string& name) {
  return "unknown model '" + name + "'; choose one of: " + xmateModels() + " (xMate, --robot HOST:PORT) or " +
         kukaModels() + " (KUKA, --robot rsi:ETHERNET.xml)";
}

bool isRsiModel(const std::string& name) {
  const xmate::model::RobotSpec* spec = xmate::model::findRobotSpec(name);
  return spec && spec->family == xmate::model::RobotFamily::kKuka;
}

void checkStateOptions(StateOptions& o) {
  if (o.robot.rsi) {
    if (o.model_name.empty())
      throw UsageError("--robot rsi:... needs --model NAME, the KUKA arm: " + kukaModels());
    if (!isRsiModel(o.model_name))
      throw UsageError("--model '" + o.model_name + "' is not a KUKA model; with --robot rsi:... choose one of: " +
                       kukaModels());
    return;
  }
  const char* rsi_only = o.bind_given ? "--bind" : o.port_given ? "--port" : o.wait_given ? "--wait" : nullptr;
  if (rsi_only)
    throw UsageError(std::string(rsi_only) + " applies to a KUKA over RSI (--robot rsi:ETHERNET.xml); leave out " +
                     rsi_only + " for an xMate controller");
  if (o.model_name.empty()) return;
  if (isRsiModel(o.model_name))
    throw UsageError("--model '" + o.model_name + "' is a KUKA arm, which speaks RSI: write --robot rsi:ETHERNET.xml");
  o.model = parseModel(o.model_name);
}

void addStateOptions(CLI::App& state, StateOptions& o) {
  addRobotOption(state, o.robot, false,
                 "HOST:PORT: an xMate controller (or rci-sim); rsi:ETHERNET.xml: a KUKA arm over RSI, answered where "
                 "that Ethernet config's IP_NUMBER and PORT say (docs/rsi.md)",
                 true)
      ->required();
  addWholeNumberOption(state, "--count", o.count, 1, 100'000'000,
                       "stop after N refreshes (RSI: N cycles) (default: until Ctrl-C)");
  addModelNameOption(state, o.model_name,
                     "the robot's model: " + xmateModels() + " (default xmate7_pro); over RSI (required): " +
                         kukaModels());
  addRsiListenOptions(state, o.listen);
  addWholeNumberOption(state, "--wait", o.wait_s, 1, 86'400,
                       "RSI: give up after S seconds without a <Rob> from the robot (default 60)")
      ->type_name("S");
}

CLI::Option* addModelNameOption(CLI::App& command, std::string& name, const std::string& help) {
  return command.add_option("--model", name, help)->type_name("NAME")->check(parsedBy([](const std::string& text) {
    if (xmate::model::findRobotSpec(text) == nullptr) throw UsageError(unknownModelText(text));
  }));
}

void addRsiContextOptions(CLI::App& command, std::string& context_path, int& cycle_ms, const std::string& context_help) {
  command.add_option("--context", context_path, context_help)->type_name("FILE");
  command.add_option("--cycle-ms", cycle_ms, "RSI: the robot's cycle, 4 (RSI_ON with #IPO_FAST) or 12")
      ->type_name("MS")
      ->check(CLI::IsMember({4, 12}));
}

void addRsiListenOptions(CLI::App& command, RsiListen& listen) {
  command.add_option("--bind", listen.bind_ip, "RSI: listen on this address of the PC instead of the config's IP_NUMBER")
      ->type_name("ADDR")
      ->check(CLI::Validator(
          [](std::string& text) {
            try {
              xmate::net::makeEndpoint(text, 0);
              return std::string();
            } catch (const std::exception&) {
              return "takes an IPv4 address of this PC (e.g. 192.168.1.20, or 0.0.0.0 for every address), got '" +
                     text + "'";
            }
          },
          ""));
  addWholeNumberOption(command, "--port", listen.port, 0, 65535,
                       "RSI: listen on this UDP port instead of the config's PORT (0: a free one, announced)");
}

CLI::Option* addRobotOption(CLI::App& command, RobotTarget& target, bool sim_allowed, const std::string& help,
                            bool rsi_allowed) {
  CLI::Option* option = command.add_option_function<std::string>(
      "--robot",
      [&target, sim_allowed, rsi_allowed](const std::string& text) {
        target = parseRobotTarget(text, sim_allowed, rsi_allowed);
      },
      help);
  option->type_name(std::string(sim_allowed ? "sim|HOST:PORT" : "HOST:PORT") +
                    (rsi_allowed ? (sim_allowed ? "|rsi:FILE|rsi-sim" : "|rsi:FILE") : ""));
  option->check(parsedBy(
      [sim_allowed, rsi_allowed](const std::string& text) { parseRobotTarget(text, sim_allowed, rsi_allowed); }));
  return option;
}

CLI::Option* addModelOption(CLI::App& command, xmate::XmateType& type, const std::string& help,
                            const std::string& name) {
  CLI::Option* option = command.add_option_function<std::string>(
      name, [&type](const std::string& text) { type = parseModel(text); }, help);
  option->type_name("NAME");
  option->check(parsedBy([](const std::string& text) { parseModel(text); }));
  return option;
}

CLI::Option* addWholeNumberOption(CLI::App& command, const std::string& name, long& value, long lo, long hi,
                                  const std::string& help) {
  CLI::Option* option =
      command.add_option(name, value, help + "; " + std::to_string(lo) + " to " + std::to_string(hi));
  option->type_name("N")->check(wholeNumber(lo, hi));
  return option;
}

}  // namespace rci_cli
