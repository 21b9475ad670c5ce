// SPDX-License-Identifier: Apache-2.0
// The command-line helpers of rci-cli (cli.h): --robot, --model and whole-number options on CLI11,
// with validators whose messages say what the option takes and what it got.
#include <charconv>

#include <CLI/CLI.hpp>

#include "cli.h"
#include "model/robot_spec.h"

namespace rci_cli {
namespace {

const char* kModels = "xmate3_pro, xmate7_pro, xmate3, xmate7";

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

// "HOST" or "HOST:PORT" (default_port when left out); UsageError ending in `expected` otherwise.
HostPort parseHostPort(const std::string& text, uint16_t default_port, const std::string& expected) {
  HostPort address;
  address.port = default_port;
  const auto colon = text.rfind(':');
  address.host = text.substr(0, colon);
  if (address.host.empty()) throw UsageError("'" + text + "': no host; " + expected);
  if (colon != std::string::npos) {
    const std::string port = text.substr(colon + 1);
    if (!wholeNumberProblem(port, 1, 65535).empty())
      throw UsageError("'" + text + "': the port must be a whole number from 1 to 65535, got '" + port + "'; " +
                       expected);
    address.port = uint16_t(std::stol(port));
  }
  return address;
}

RobotTarget parseRobotTarget(const std::string& text, bool sim_allowed) {
  const std::string expected = sim_allowed ? "write sim (the in-process simulator) or HOST:PORT, e.g. 127.0.0.1:1337"
                                           : "write HOST:PORT, e.g. 127.0.0.1:1337";
  RobotTarget target;
  if (text == "sim") {
    if (!sim_allowed) throw UsageError("'sim': this command needs a controller address; " + expected);
    target.in_process = true;
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
  if (const auto* spec = xmate::model::findRobotSpec(text)) return spec->type;
  throw UsageError("unknown model '" + text + "'; choose one of: " + kModels);
}

CLI::Option* addRobotOption(CLI::App& command, RobotTarget& target, bool sim_allowed, const std::string& help) {
  CLI::Option* option = command.add_option_function<std::string>(
      "--robot", [&target, sim_allowed](const std::string& text) { target = parseRobotTarget(text, sim_allowed); },
      help);
  option->type_name(sim_allowed ? "sim|HOST:PORT" : "HOST:PORT");
  option->check(parsedBy([sim_allowed](const std::string& text) { parseRobotTarget(text, sim_allowed); }));
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
