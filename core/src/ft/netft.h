// SPDX-License-Identifier: Apache-2.0
// ft::NetFtClient: an ATI Net F/T force/torque sensor read over RDT (UDP), the sensor the KUKA
// hand-guiding needs. It asks the sensor to stream, receives its records on its own thread,
// converts counts to N and Nm, subtracts a bias taken on request, and publishes the newest wrench
// (seqlock) with rate and loss statistics. docs/rsi.md, "The force/torque sensor".
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "net/seqlock.h"
#include "net/udp_socket.h"

namespace xmate::ft {

// The RDT wire format (big-endian): request {uint16 0x1234, uint16 command, uint32 count};
// response {uint32 rdt_sequence, uint32 ft_sequence, uint32 status, int32 Fx Fy Fz Tx Ty Tz}.
inline constexpr uint16_t kRdtHeader = 0x1234;
inline constexpr uint16_t kCommandStop = 0x0000;
inline constexpr uint16_t kCommandStartStreaming = 0x0002;
inline constexpr uint16_t kCommandSetBias = 0x0042;
inline constexpr size_t kRequestBytes = 8;
inline constexpr size_t kRecordBytes = 36;
inline constexpr uint16_t kDefaultPort = 49152;

struct RdtRecord {
  uint32_t rdt_sequence = 0;
  uint32_t ft_sequence = 0;
  uint32_t status = 0;
  std::array<int32_t, 6> counts{};  // Fx Fy Fz Tx Ty Tz
};
void encodeRequest(uint16_t command, uint32_t count, uint8_t out[kRequestBytes]);
// False unless exactly kRequestBytes starting with kRdtHeader (for simulated sensors).
bool decodeRequest(const uint8_t* data, size_t size, uint16_t& command);
// False unless exactly kRecordBytes.
bool decodeRecord(const uint8_t* data, size_t size, RdtRecord& out);
void encodeRecord(const RdtRecord& record, uint8_t out[kRecordBytes]);  // for simulated sensors

struct NetFtOptions {
  std::string host;                    // the sensor's address
  uint16_t port = kDefaultPort;
  double counts_per_force = 1e6;       // counts per N (the sensor's configuration)
  double counts_per_torque = 1e6;      // counts per Nm
  int silence_ms = 100;                // no record for this long: the sensor fell silent
};

// The newest reading, for other threads (trivially copyable).
struct Wrench {
  std::array<double, 6> values{};  // Fx Fy Fz (N), Tx Ty Tz (Nm), bias subtracted
  uint32_t rdt_sequence = 0;
  uint32_t status = 0;             // the sensor's status word (0: healthy)
  int64_t received_ns = 0;
};

struct NetFtStatistics {
  uint64_t records = 0;     // records received
  uint64_t lost = 0;        // gaps in rdt_sequence
  uint64_t malformed = 0;   // datagrams that were not a record
  double rate_hz = 0;       // records per second over the last second
};

class NetFtClient {
 public:
  explicit NetFtClient(NetFtOptions options);
  ~NetFtClient();  // stop()
  NetFtClient(const NetFtClient&) = delete;
  NetFtClient& operator=(const NetFtClient&) = delete;

  // Any thread, not real-time. start() binds a local port, asks the sensor to stream and starts
  // the receiving thread; throws std::runtime_error (a bad address) saying what to fix.
  void start();
  // Asks the sensor to stop streaming and joins the thread.
  void stop();

  // Any thread, lock-free.
  bool latest(Wrench& out) const { return latest_.load(out) > 0; }
  bool streaming() const { return streaming_.load(std::memory_order_acquire); }
  NetFtStatistics statistics() const;
  // The next record's reading becomes the zero (software bias; the sensor keeps its own).
  void bias() { bias_requested_.store(true, std::memory_order_release); }
  void clearBias() { clear_bias_requested_.store(true, std::memory_order_release); }

 private:
  void run();

  const NetFtOptions options_;
  net::Endpoint sensor_;
  net::UdpSocket socket_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> streaming_{false};
  std::atomic<bool> bias_requested_{false};
  std::atomic<bool> clear_bias_requested_{false};
  std::array<double, 6> bias_{};
  net::Seqlock<Wrench> latest_;
  net::Seqlock<NetFtStatistics> statistics_;
};

}  // namespace xmate::ft
