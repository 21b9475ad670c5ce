// SPDX-License-Identifier: Apache-2.0
// NetFtClient (netft.h): the RDT codec and the receiving thread.
#include "ft/netft.h"

#include <stdexcept>

#include "net/clock.h"
#include "net/realtime.h"

namespace xmate::ft {
namespace {

constexpr int64_t kReceiveWaitUs = 10000;
constexpr int64_t kRequestAgainNs = 500'000'000;  // a silent sensor is asked to stream again this often

void put16(uint8_t* p, uint16_t v) {
  p[0] = uint8_t(v >> 8);
  p[1] = uint8_t(v);
}
uint16_t get16(const uint8_t* p) { return uint16_t(p[0] << 8 | p[1]); }
void put32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = uint8_t(v >> (24 - 8 * i));
}
uint32_t get32(const uint8_t* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

}  // namespace

void encodeRequest(uint16_t command, uint32_t count, uint8_t out[kRequestBytes]) {
  put16(out, kRdtHeader);
  put16(out + 2, command);
  put32(out + 4, count);
}

bool decodeRequest(const uint8_t* data, size_t size, uint16_t& command) {
  if (size != kRequestBytes || get16(data) != kRdtHeader) return false;
  command = get16(data + 2);
  return true;
}

bool decodeRecord(const uint8_t* data, size_t size, RdtRecord& out) {
  if (size != kRecordBytes) return false;
  out.rdt_sequence = get32(data);
  out.ft_sequence = get32(data + 4);
  out.status = get32(data + 8);
  for (size_t i = 0; i < 6; ++i) out.counts[i] = int32_t(get32(data + 12 + 4 * i));
  return true;
}

void encodeRecord(const RdtRecord& r, uint8_t out[kRecordBytes]) {
  put32(out, r.rdt_sequence);
  put32(out + 4, r.ft_sequence);
  put32(out + 8, r.status);
  for (size_t i = 0; i < 6; ++i) put32(out + 12 + 4 * i, uint32_t(r.counts[i]));
}

NetFtClient::NetFtClient(NetFtOptions options) : options_(std::move(options)) {}

NetFtClient::~NetFtClient() { stop(); }

void NetFtClient::start() {
  if (thread_.joinable()) return;
  if (!(options_.counts_per_force > 0 && options_.counts_per_torque > 0))
    throw std::runtime_error("F/T sensor: counts per N and per Nm must be positive (the sensor's configuration, "
                             "often 1000000)");
  try {
    sensor_ = net::makeEndpoint(options_.host, options_.port);
  } catch (const std::exception& e) {
    throw std::runtime_error("F/T sensor: \"" + options_.host + "\" is not an IPv4 address (" + e.what() +
                             "); give the sensor's address, e.g. 192.168.1.1");
  }
  socket_.bind("0.0.0.0", 0);
  stop_.store(false);
  thread_ = std::thread([this] { run(); });
}

void NetFtClient::stop() {
  if (!thread_.joinable()) return;
  stop_.store(true);
  thread_.join();
  uint8_t request[kRequestBytes];
  encodeRequest(kCommandStop, 0, request);
  socket_.sendTo(sensor_, request, sizeof request);
  socket_.close();
  streaming_.store(false);
}

NetFtStatistics NetFtClient::statistics() const {
  NetFtStatistics s;
  statistics_.load(s);
  return s;
}

void NetFtClient::run() {
  net::nameThisThread("rci-ft");
  uint8_t request[kRequestBytes];
  encodeRequest(kCommandStartStreaming, 0, request);  // 0: stream until told to stop
  NetFtStatistics stats;
  int64_t last_record_ns = 0, last_request_ns = 0, window_start_ns = net::monotonicNs();
  uint64_t window_records = 0;
  bool have_sequence = false;
  uint32_t last_sequence = 0;
  uint8_t datagram[64];
  while (!stop_.load(std::memory_order_acquire)) {
    const int64_t now = net::monotonicNs();
    if (now - last_record_ns > int64_t(options_.silence_ms) * 1'000'000) {
      streaming_.store(false, std::memory_order_release);
      if (now - last_request_ns > kRequestAgainNs) {  // first start, or the sensor restarted
        socket_.sendTo(sensor_, request, sizeof request);
        last_request_ns = now;
      }
    }
    net::Endpoint from;
    const long n = socket_.receiveFrom(datagram, sizeof datagram, &from, kReceiveWaitUs);
    if (n <= 0) continue;
    RdtRecord record;
    if (!decodeRecord(datagram, size_t(n), record)) {
      ++stats.malformed;
      statistics_.store(stats);
      continue;
    }
    const int64_t received = net::monotonicNs();
    if (have_sequence && record.rdt_sequence > last_sequence + 1) stats.lost += record.rdt_sequence - last_sequence - 1;
    have_sequence = true;
    last_sequence = record.rdt_sequence;
    ++stats.records;
    ++window_records;
    if (received - window_start_ns >= 1'000'000'000) {
      stats.rate_hz = double(window_records) * 1e9 / double(received - window_start_ns);
      window_records = 0;
      window_start_ns = received;
    }
    Wrench w;
    for (size_t i = 0; i < 6; ++i)
      w.values[i] = double(record.counts[i]) / (i < 3 ? options_.counts_per_force : options_.counts_per_torque);
    if (clear_bias_requested_.exchange(false, std::memory_order_acq_rel)) bias_ = {};
    if (bias_requested_.exchange(false, std::memory_order_acq_rel)) bias_ = w.values;
    for (size_t i = 0; i < 6; ++i) w.values[i] -= bias_[i];
    w.rdt_sequence = record.rdt_sequence;
    w.status = record.status;
    w.received_ns = received;
    latest_.store(w);
    statistics_.store(stats);
    last_record_ns = received;
    streaming_.store(true, std::memory_order_release);
  }
}

}  // namespace xmate::ft
