// SPDX-License-Identifier: Apache-2.0
// sim::SimulatedFtSensor: an ATI Net F/T sensor as its RDT clients see it -- a start request makes
// it stream records to the requester at a fixed rate until a stop request -- with the wrench it
// reads set from outside (a simulated arm's external force, a test). rci-sim --ft-sensor serves one.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "net/seqlock.h"
#include "net/udp_socket.h"

namespace xmate::sim {

struct FtSensorConfig {
  std::string bind_ip = "127.0.0.1";
  uint16_t port = 49152;         // 0 picks a free port
  double rate_hz = 1000;         // records per second while streaming
  double counts_per_unit = 1e6;  // counts per N and per Nm
};

class SimulatedFtSensor {
 public:
  explicit SimulatedFtSensor(FtSensorConfig config = {});
  ~SimulatedFtSensor();  // stop()
  SimulatedFtSensor(const SimulatedFtSensor&) = delete;
  SimulatedFtSensor& operator=(const SimulatedFtSensor&) = delete;

  // Binds and starts the thread; throws std::runtime_error saying which address could not be bound.
  void start();
  void stop();
  uint16_t port() const { return port_; }

  // Any thread. The wrench the sensor reads: Fx Fy Fz (N), Tx Ty Tz (Nm).
  void setWrench(const std::array<double, 6>& wrench) { wrench_.store(wrench); }
  // Faults for tests and demonstrations: stop sending while silent; records with rdt_sequence in
  // [first, first + count) are never sent (lost on the way).
  void setSilent(bool silent) { silent_.store(silent); }
  void dropRecords(uint32_t first, uint32_t count) {
    drop_first_.store(first);
    drop_count_.store(count);
  }
  int startRequests() const { return starts_.load(); }
  int stopRequests() const { return stops_.load(); }

 private:
  void run();

  const FtSensorConfig config_;
  net::UdpSocket socket_;
  uint16_t port_ = 0;
  std::thread thread_;
  std::atomic<bool> quit_{false};
  std::atomic<bool> silent_{false};
  std::atomic<uint32_t> drop_first_{0}, drop_count_{0};
  std::atomic<int> starts_{0}, stops_{0};
  net::Seqlock<std::array<double, 6>> wrench_;
};

}  // namespace xmate::sim
