// SPDX-License-Identifier: Apache-2.0
// rsi::Link (link.h): the receive -> decode -> callback -> encode -> send loop on its own thread.
#include "rsi/link.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "net/clock.h"

namespace xmate::rsi {
namespace {

constexpr int64_t kReceiveWaitUs = 5000;  // how often the thread looks at stop_ and at the silence

const char* const kAxisNames[6] = {"A1", "A2", "A3", "A4", "A5", "A6"};
const char* const kCartesianNames[6] = {"X", "Y", "Z", "A", "B", "C"};

}  // namespace

Link::Link(const EthernetConfig& config, LinkOptions options)
    : config_(config), options_(std::move(options)), decoder_(config), encoder_(config, options_.precision) {
  for (size_t i = 0; i < 6; ++i) {
    axis_slots_[i] = encoder_.slot("AK", kAxisNames[i]);
    cartesian_slots_[i] = encoder_.slot("RK", kCartesianNames[i]);
  }
}

Link::~Link() { stop(); }

void Link::setCallback(Callback callback) {
  if (thread_.joinable()) throw std::logic_error("rsi::Link::setCallback: set the callback before start()");
  callback_ = std::move(callback);
}

void Link::start() {
  if (thread_.joinable()) return;
  const std::string ip = !options_.bind_ip.empty() ? options_.bind_ip : config_.ip_is_placeholder ? "0.0.0.0" : config_.ip;
  const uint16_t port = options_.port >= 0 ? uint16_t(options_.port) : config_.port;
  try {
    socket_.bind(ip, port);
  } catch (const std::exception& e) {
    throw std::runtime_error("RSI: cannot listen on " + ip + ":" + std::to_string(port) + " (" + e.what() +
                             "); IP_NUMBER in " + config_.path +
                             " must be an address of this PC, and no other program may use the port");
  }
  port_ = socket_.localPort();
  stop_.store(false);
  thread_ = std::thread([this] { run(); });
}

void Link::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  socket_.close();
  receiving_.store(false);
}

LinkCounters Link::counters() const {
  LinkCounters c;
  counters_.load(c);
  return c;
}

net::RealtimeStatus Link::realtimeStatus() const {
  if (!status_ready_.load(std::memory_order_acquire)) return {};
  return status_;
}

void Link::newSession() {
  ++session_;
  ++counting_.sessions;
  last_total_ = {};
}

void Link::setReceiveValue(int slot, double value) {
  if (slot < 0 || size_t(slot) >= encoder_.layout().size() || size_t(slot) >= kMaxSlots)
    throw std::out_of_range("rsi::Link::setReceiveValue: slot " + std::to_string(slot) +
                            " is not a RECEIVE element of " + config_.path);
  receive_values_[size_t(slot)].value.store(value, std::memory_order_relaxed);
  receive_values_[size_t(slot)].set.store(true, std::memory_order_release);
  receive_pending_.store(true, std::memory_order_release);
}

void Link::takeReceiveValues() {
  if (!receive_pending_.exchange(false, std::memory_order_acq_rel)) return;
  const size_t n = std::min(encoder_.layout().size(), kMaxSlots);
  for (size_t i = 0; i < n; ++i)
    if (receive_values_[i].set.exchange(false, std::memory_order_acq_rel))
      encoder_.set(int(i), receive_values_[i].value.load(std::memory_order_relaxed));
}

int64_t Link::answer(const net::Endpoint& to, int64_t received_ns) {
  takeReceiveValues();
  const Correction c = callback_ ? callback_(decoder_) : Correction{};
  if (c.kind != Correction::Kind::kNone) {
    const auto& slots = c.kind == Correction::Kind::kAxis ? axis_slots_ : cartesian_slots_;
    for (size_t i = 0; i < 6; ++i) {
      const double sent = options_.mode == CorrectionMode::kAbsolute ? c.values[i] : c.values[i] - last_total_[i];
      if (slots[i] >= 0) encoder_.set(slots[i], sent);
    }
    last_total_ = c.values;
  }
  if (config_.only_send) return -1;
  char out[kMaxSenBytes];
  const size_t n = encoder_.encode(decoder_.ipocText(), out, sizeof out);
  if (n == 0 || socket_.sendTo(to, out, n) != long(n)) {
    ++counting_.send_failures;
    return -1;
  }
  ++counting_.answered;
  return net::monotonicNs() - received_ns;
}

void Link::run() {
  net::nameThisThread("rci-rsi");
  if (options_.realtime)
    status_ = net::enableRealtimeForThisThread(options_.priority, {{this, sizeof *this}});
  else
    status_.reason = "real-time scheduling not requested";
  status_ready_.store(true, std::memory_order_release);

  int64_t last_received_ns = 0;
  while (!stop_.load(std::memory_order_acquire)) {
    net::Endpoint from;
    const long n = socket_.receiveFrom(datagram_.data(), datagram_.size(), &from, kReceiveWaitUs);
    const int64_t now = net::monotonicNs();
    if (n <= 0) {
      if (receiving_.load(std::memory_order_relaxed) && now - last_received_ns > int64_t(options_.silence_ms) * 1'000'000)
        receiving_.store(false, std::memory_order_release);  // RSI off, stopped, or the cable
      continue;
    }
    if (!decoder_.decode({datagram_.data(), size_t(std::min<long>(n, long(datagram_.size())))})) {
      ++counting_.rejected;
      last_reason_.store(decoder_.reason(), std::memory_order_release);
      counters_.store(counting_);
      continue;
    }
    if (!receiving_.load(std::memory_order_relaxed)) newSession();  // the robot (re)started sending
    receiving_.store(true, std::memory_order_release);
    last_received_ns = now;
    ++counting_.received;
    // Published before the answer goes out; the counters after it (they count the answer).
    RobSample sample;
    sample.ipoc = decoder_.ipoc();
    sample.received_ns = now;
    sample.session = session_;
    sample.count = uint32_t(std::min(decoder_.layout().size(), kMaxSlots));
    for (uint32_t i = 0; i < sample.count; ++i) sample.values[i] = decoder_.value(int(i));
    latest_.store(sample);
    const int64_t took = answer(from, now);
    LinkSample brief;
    brief.late = took > int64_t(options_.cycle_ms) * 1'000'000;  // the robot counts it in Delay
    if (brief.late) ++counting_.late;
    counters_.store(counting_);
    brief.ipoc = sample.ipoc;
    brief.received_ns = now;
    brief.answer_ns = took < 0 ? -1 : int32_t(std::min<int64_t>(took, INT32_MAX));
    brief.session = session_;
    brief.count = uint32_t(std::min<size_t>(sample.count, kSampleSlots));
    for (uint32_t i = 0; i < brief.count; ++i) brief.values[i] = sample.values[i];
    samples_->push(brief);
  }
}

}  // namespace xmate::rsi
