// SPDX-License-Identifier: Apache-2.0
// Argument helpers and the usage text of rci-cli.
#include <cerrno>
#include <cstdlib>

#include "cli.h"
#include "model/robot_spec.h"

namespace rci_cli {

std::string Args::value(const std::string& name) {
  if (done()) throw UsageError(name + " needs a value");
  return take();
}

HostPort parseHostPort(const std::string& option, const std::string& text) {
  HostPort hp;
  const auto colon = text.rfind(':');
  hp.host = text.substr(0, colon);
  if (hp.host.empty()) throw UsageError(option + " '" + text + "': expected HOST:PORT, e.g. 127.0.0.1:1337");
  if (colon != std::string::npos) hp.port = uint16_t(parseInteger(option + " port", text.substr(colon + 1), 1, 65535));
  return hp;
}

long parseInteger(const std::string& option, const std::string& text, long lo, long hi) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
    throw UsageError(option + " '" + text + "': expected an integer in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return v;
}

xmate::XmateType parseModel(const std::string& option, const std::string& text) {
  if (const auto* spec = xmate::model::findRobotSpec(text)) return spec->type;
  throw UsageError(option + " '" + text + "': unknown model (known: xmate3_pro, xmate7_pro, xmate3, xmate7)");
}

std::string usage() {
  return "usage:\n"
         "  rci-cli [model NAME]                      limits of a model (default xmate7_pro)\n"
         "  rci-cli state --robot HOST:PORT [--count N] [--model NAME]\n"
         "                                            live readout of the robot's state (N refreshes; default: until Ctrl-C)\n"
         "  rci-cli run PROGRAM.json --robot sim|HOST:PORT [--model NAME] [--speed R] [--report REPORT.json] [--fast]\n"
         "                                            run a taught program (docs/teach.md): pre-flight, then replay;\n"
         "                                            sim = in-process simulator on its real-time clock (--fast: lock-step,\n"
         "                                            faster than real time); R = speed override 0.1..1.0\n"
         "  rci-cli doctor                            real-time fitness of this machine, with advice\n"
         "  rci-cli bench loop [--robot sim|HOST:PORT] [--cycles N] [--lockstep] [--model NAME]\n"
         "                                            1 kHz joint-position loop: period, jitter, late/lost cycles\n"
         "  rci-cli bench client [--cycles N]         client cost per cycle (decode, callback, encode, send)\n"
         "  rci-cli help                              this text\n";
}

}  // namespace rci_cli
