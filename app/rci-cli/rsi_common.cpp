// SPDX-License-Identifier: Apache-2.0
// What the commands that drive a KUKA over RSI share (run, guide): finding the RSI context the
// robot runs, and waiting for the robot to start sending.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cli.h"
#include "rsi/config.h"
#include "arm/joint_stream.h"
#include "rsi/link.h"

namespace rci_cli {

// The RSI context beside `config_path` whose ETHERNET object names that file.
std::string contextNaming(const std::string& config_path) {
  const std::vector<std::string> found = xmate::rsi::contextsNaming(config_path);
  if (found.size() == 1) return found.front();
  throw std::runtime_error(
      (found.empty() ? "no RSI context (NAME.rsi.xml) beside " + config_path + " names it"
                     : std::to_string(found.size()) + " RSI contexts beside " + config_path + " name it") +
      "; give the one the robot runs with --context NAME.rsi.xml (its AXISCORR limits bound every motion)");
}

// Waits (at most a minute) until the robot sends; says what to do meanwhile.
void waitForRsi(const xmate::rsi::Link& link, const xmate::arm::JointStream& stream, const std::string& where,
                const std::atomic<bool>& interrupted) {
  std::printf("waiting for the robot on %s -- start the KRL program with RSI_ON and RSI_MOVECORR\n", where.c_str());
  std::fflush(stdout);
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  xmate::arm::StreamState s;
  while (!(link.receiving() && stream.state(s))) {
    if (std::chrono::steady_clock::now() > end || interrupted.load())
      throw std::runtime_error("no <Rob> datagram arrived on " + where +
                               " within 60 s: check that the KRL program runs RSI_ON, that IP_NUMBER and PORT in "
                               "the Ethernet config name this PC, and that no firewall blocks the port");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace rci_cli
