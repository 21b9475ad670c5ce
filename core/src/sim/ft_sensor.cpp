// SPDX-License-Identifier: Apache-2.0
// SimulatedFtSensor (ft_sensor.h): one thread answers requests and streams records on a clock.
#include "sim/ft_sensor.h"

#include <cmath>
#include <stdexcept>

#include "ft/netft.h"
#include "net/clock.h"
#include "net/realtime.h"

namespace xmate::sim {

SimulatedFtSensor::SimulatedFtSensor(FtSensorConfig config) : config_(std::move(config)) {
  wrench_.store(std::array<double, 6>{});
}

SimulatedFtSensor::~SimulatedFtSensor() { stop(); }

void SimulatedFtSensor::start() {
  if (thread_.joinable()) return;
  if (!(config_.rate_hz > 0 && config_.counts_per_unit > 0))
    throw std::runtime_error("simulated F/T sensor: the rate and the counts per unit must be positive");
  try {
    socket_.bind(config_.bind_ip, config_.port);
  } catch (const std::exception& e) {
    throw std::runtime_error("simulated F/T sensor: cannot listen on " + config_.bind_ip + ":" +
                             std::to_string(config_.port) + " (" + e.what() + "); choose another port");
  }
  port_ = socket_.localPort();
  quit_.store(false);
  thread_ = std::thread([this] { run(); });
}

void SimulatedFtSensor::stop() {
  quit_.store(true);
  if (thread_.joinable()) thread_.join();
  socket_.close();
}

void SimulatedFtSensor::run() {
  net::nameThisThread("rci-sim-ft");
  const int64_t period_ns = int64_t(1e9 / config_.rate_hz);
  net::Endpoint client;
  bool streaming = false;
  uint32_t sequence = 0;
  int64_t next_ns = net::monotonicNs();
  while (!quit_.load()) {
    const int64_t wait_us = std::max<int64_t>(0, (next_ns - net::monotonicNs()) / 1000);
    uint8_t request[16];
    net::Endpoint from;
    const long n = socket_.receiveFrom(request, sizeof request, &from, streaming ? wait_us : 10'000);
    uint16_t command = 0;
    if (n > 0 && ft::decodeRequest(request, size_t(n), command)) {
      if (command == ft::kCommandStartStreaming) {
        ++starts_;
        client = from;
        streaming = true;
        next_ns = net::monotonicNs();
      } else if (command == ft::kCommandStop) {
        ++stops_;
        streaming = false;
      }
      continue;
    }
    if (!streaming || net::monotonicNs() < next_ns) continue;
    next_ns += period_ns;
    ++sequence;
    if (silent_.load()) continue;
    const uint32_t first = drop_first_.load();
    if (sequence >= first && sequence < first + drop_count_.load()) continue;
    std::array<double, 6> wrench{};
    wrench_.load(wrench);
    ft::RdtRecord r;
    r.rdt_sequence = sequence;
    r.ft_sequence = sequence;
    for (size_t i = 0; i < 6; ++i) r.counts[i] = int32_t(std::llround(wrench[i] * config_.counts_per_unit));
    uint8_t out[ft::kRecordBytes];
    ft::encodeRecord(r, out);
    socket_.sendTo(client, out, sizeof out);
  }
}

}  // namespace xmate::sim
