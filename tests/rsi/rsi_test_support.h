// SPDX-License-Identifier: Apache-2.0
// What the RSI tests share: the sample Ethernet config, link options on loopback, and a fake robot
// that sends <Rob> datagrams from its own port (as a KRC does) and reads each answer.
#pragma once

#include <QtGlobal>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

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
