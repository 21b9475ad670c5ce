// SPDX-License-Identifier: Apache-2.0
// sim::KrcServer (krc_server.h): the socket, the timed thread and lock-step steps around sim::Krc.
#include "sim/krc_server.h"

#include <algorithm>
#include <stdexcept>

#include "net/clock.h"
#include "sim/ft_sensor.h"

namespace xmate::sim {

KrcServer::KrcServer(KrcServerConfig config) : config_(std::move(config)), krc_(std::make_unique<Krc>(config_.krc)) {
  const rsi::EthernetConfig& eth = krc_->ethernetConfig();
  std::string ip = config_.target_ip;
  if (ip.empty()) {
    if (eth.ip_is_placeholder)
      throw std::runtime_error("the Ethernet config " + eth.path + " gives IP_NUMBER \"" + eth.ip +
                               "\", which is not an address; give the PC's address as the target "
                               "(rci-sim --rsi-target HOST:PORT)");
    ip = eth.ip;
  }
  const uint16_t port = config_.target_port != 0 ? config_.target_port : eth.port;
  try {
    target_ = net::makeEndpoint(ip, port);
  } catch (const std::exception& e) {
    throw std::runtime_error("RSI target " + ip + ":" + std::to_string(port) + " is not an IPv4 address and port (" +
                             e.what() + "); give HOST:PORT of the PC, e.g. 127.0.0.1:49152");
  }
  try {
    socket_.bind(config_.bind_ip, config_.bind_port);
  } catch (const std::exception& e) {
    throw std::runtime_error("simulated KRC: cannot bind its UDP socket to " + config_.bind_ip + ":" +
                             std::to_string(config_.bind_port) + " (" + e.what() +
                             "); give an address of this machine and a free port (0 picks one)");
  }
  port_ = socket_.localPort();
}

KrcServer::~KrcServer() { stop(); }

std::string KrcServer::target() const { return target_.toString(); }

net::RealtimeStatus KrcServer::realtimeStatus() const {
  if (!status_ready_.load(std::memory_order_acquire)) return {};
  return status_;
}

void KrcServer::start() {
  if (thread_.joinable()) return;
  quit_.store(false);
  thread_ = std::thread([this] { run(); });
}

void KrcServer::stop() {
  quit_.store(true);
  if (thread_.joinable()) thread_.join();
}

bool KrcServer::step() {
  if (thread_.joinable()) throw std::logic_error("KrcServer::step: the timed thread runs; stop() it first");
  return cycle(net::monotonicNs() + int64_t(config_.lockstep_timeout_ms) * 1'000'000, true);
}

bool KrcServer::cycle(int64_t deadline_ns, bool stop_when_answered) {
  Krc& krc = *krc_;
  const size_t n = krc.beginCycle(out_.data(), out_.size());
  if (n > 0) {
    const int copies = krc.takeDuplicate() ? 2 : 1;
    for (int i = 0; i < copies; ++i)
      if (socket_.sendTo(target_, out_.data(), n) != long(n)) send_failures_.fetch_add(1, std::memory_order_relaxed);
  }
  // Lock-step waits only for an answer it needs; the timed loop keeps the clock (and reads what comes).
  const bool wait = stop_when_answered ? krc.awaitingAnswer() : true;
  waited_ = wait;
  while (wait) {
    const int64_t left_ns = deadline_ns - net::monotonicNs();
    if (left_ns <= 0) break;
    net::Endpoint from;
    const long got = socket_.receiveFrom(in_.data(), in_.size(), &from, std::max<int64_t>(1, left_ns / 1000));
    if (got > 0) krc.onAnswer({in_.data(), size_t(std::min<long>(got, long(in_.size())))});
    if (got < 0) net::sleepUntilNs(std::min(deadline_ns, net::monotonicNs() + 1'000'000));  // an error: do not spin
    if (stop_when_answered && krc.answered()) break;
  }
  const bool answered = krc.answered();
  krc.endCycle();
  if (config_.ft_sensor) config_.ft_sensor->setWrench(krc.flangeWrench());
  return answered;
}

void KrcServer::run() {
  net::nameThisThread("rci-krc");
  if (config_.realtime)
    status_ = net::enableRealtimeForThisThread(config_.realtime_priority, {{this, sizeof *this}});
  else
    status_.reason = "real-time scheduling not requested";
  status_ready_.store(true, std::memory_order_release);
  const int64_t period_ns = int64_t(krc_->cycleMs()) * 1'000'000;
  if (config_.lockstep) {
    while (!quit_.load(std::memory_order_acquire)) {
      const int64_t start_ns = net::monotonicNs();
      cycle(start_ns + int64_t(config_.lockstep_timeout_ms) * 1'000'000, true);
      if (!waited_) net::sleepUntilNs(start_ns + period_ns);  // RSI off: the KRC's clock runs at wall time
    }
    return;
  }
  int64_t next_ns = net::monotonicNs();
  while (!quit_.load(std::memory_order_acquire)) {
    const int64_t deadline_ns = next_ns + period_ns;
    cycle(deadline_ns, false);
    next_ns = deadline_ns;
    const int64_t now = net::monotonicNs();
    if (now > next_ns + period_ns) next_ns = now;  // fell behind (a paused VM): no burst of cycles to catch up
  }
}

}  // namespace xmate::sim
