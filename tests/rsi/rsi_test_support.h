// SPDX-License-Identifier: Apache-2.0
// What the RSI tests share: the sample Ethernet config, link options on loopback, a fake robot
// that sends <Rob> datagrams from its own port (as a KRC does) and reads each answer, and a KUKA
// cell on loopback (an arm::RsiArm and the simulated KRC sending to it).
#pragma once

#include <QtGlobal>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>

#include "arm/rsi_arm.h"
#include "sim/krc_server.h"

#include "net/udp_socket.h"
#include "rsi/config.h"
#include "rsi/link.h"

namespace xmate::rsi::testing {

inline std::string dataPath(const std::string& relative) {
  return qEnvironmentVariable("RCI_DATA_DIR").toStdString() + "/" + relative;
}

inline EthernetConfig sampleConfig() { return readEthernetConfig(dataPath("resources/rsi/RSI_EthernetConfig.xml")); }

inline LinkOptions loopback(CorrectionMode mode = CorrectionMode::kAbsolute) {
  LinkOptions o;
  o.bind_ip = "127.0.0.1";
  o.port = 0;  // a free port
  o.mode = mode;
  o.realtime = false;
  o.silence_ms = 1000;  // a loaded machine may pause between two exchanges; only the test's own pause is silence
  return o;
}

// Polls `condition` every millisecond for at most `limit_ms`.
inline bool waitFor(const std::function<bool()>& condition, int limit_ms = 15000) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(limit_ms);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// A KUKA arm on loopback (a free port, no real-time scheduling) running `context` (a path under the
// data directory, e.g. "resources/rsi/rci_replay.rsi.xml").
inline arm::RsiArmConfig loopbackArm(const std::string& context, int silence_ms = 1000,
                                     const std::string& model = "kr6_r900_sixx") {
  arm::RsiArmConfig config;
  config.context_path = dataPath(context);
  config.model = model;
  config.link = loopback();
  config.link.silence_ms = silence_ms;
  return config;
}

// The simulated KRC for that arm, sending to `port` (the arm's started link), timed or in lock-step.
inline sim::KrcServerConfig krcFor(const arm::RsiArmConfig& arm, uint16_t port, bool lockstep) {
  sim::KrcServerConfig k;
  k.krc.context_path = arm.context_path;
  k.krc.model = arm.model;
  k.target_ip = "127.0.0.1";
  k.target_port = port;
  k.lockstep = lockstep;
  k.lockstep_timeout_ms = 500;
  return k;
}

class FakeRobot {
 public:
  explicit FakeRobot(uint16_t link_port) : to_(net::makeEndpoint("127.0.0.1", link_port)) { socket_.bind("127.0.0.1", 0); }

  // Sends a <Rob> with this IPOC and A1 actual; returns the answer ("" if none within 2 s).
  std::string exchange(uint64_t ipoc, double a1 = 0, const std::string& raw = {}) {
    return send(!raw.empty() ? raw
                             : "<Rob Type=\"ImFree\"><AIPos A1=\"" + std::to_string(a1) +
                                   "\" A2=\"-90\" A3=\"90\" A4=\"0\" A5=\"90\" A6=\"0\" /><Delay D=\"0\" /><IPOC>" +
                                   std::to_string(ipoc) + "</IPOC></Rob>");
  }

  // Sends a <Rob> with these actual and set-point axes (deg).
  std::string exchangeAxes(uint64_t ipoc, const std::array<double, 6>& actual, const std::array<double, 6>& set) {
    return send("<Rob Type=\"ImFree\">" + axes("AIPos", actual) + axes("ASPos", set) + "<IPOC>" + std::to_string(ipoc) +
                "</IPOC></Rob>");
  }

 private:
  static std::string axes(const char* element, const std::array<double, 6>& a) {
    std::string out = std::string("<") + element;
    char value[64];
    for (int i = 0; i < 6; ++i) {
      std::snprintf(value, sizeof value, " A%d=\"%.6f\"", i + 1, a[size_t(i)]);
      out += value;
    }
    return out + " />";
  }
  std::string send(const std::string& rob) {
    socket_.sendTo(to_, rob.data(), rob.size());
    char buffer[2048];
    net::Endpoint from;
    const long n = socket_.receiveFrom(buffer, sizeof buffer, &from, 2'000'000);
    return n > 0 ? std::string(buffer, size_t(n)) : std::string();
  }

  net::UdpSocket socket_;
  net::Endpoint to_;
};

// The attribute's value in an answer (NaN if absent).
inline double attribute(const std::string& sen, const std::string& name) {
  const size_t at = sen.find(" " + name + "=\"");
  return at == std::string::npos ? NAN : std::stod(sen.substr(at + name.size() + 3));
}

}  // namespace xmate::rsi::testing
