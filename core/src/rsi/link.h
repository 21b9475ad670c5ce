// SPDX-License-Identifier: Apache-2.0
// rsi::Link, the PC side of RSI (the counterpart of xmate::Robot for a KUKA): binds the Ethernet
// config's address and port, answers every <Rob> to the address and port it came from on a
// real-time thread, with the corrections a per-cycle callback returns, publishes the newest values
// (seqlock), counts what went wrong, notices when the robot stops sending and starts a new session
// when it sends again. docs/rsi.md, "The link".
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "net/realtime.h"
#include "net/seqlock.h"
#include "net/spsc_ring.h"
#include "net/udp_socket.h"
#include "rsi/codec.h"
#include "rsi/config.h"

namespace xmate::rsi {

// How the KRL program started RSI (RSI_ON(#ABSOLUTE) or RSI_ON(#RELATIVE)).
enum class CorrectionMode { kAbsolute, kRelative };

// What the callback wants the robot to do this cycle: axis corrections A1..A6 (deg, into the
// config's AK.A1..A6) or Cartesian corrections X Y Z (mm) A B C (deg, into RK.X..RK.C) -- always
// the total since RSI was switched on; the link turns it into what the mode expects (#RELATIVE:
// the change since the last cycle). kNone sends the RECEIVE elements as they are.
struct Correction {
  enum class Kind { kNone, kAxis, kCartesian };
  Kind kind = Kind::kNone;
  std::array<double, 6> values{};
};

struct LinkOptions {
  std::string bind_ip;   // "": the config's IP_NUMBER, or every address if that is a placeholder
  int port = -1;         // -1: the config's PORT; 0: a free port (port() tells which)
  int precision = 4;     // decimals of DOUBLE values (the context's ETHERNET Precision)
  CorrectionMode mode = CorrectionMode::kAbsolute;
  int cycle_ms = 4;      // 4 (#IPO_FAST) or 12: an answer later than this after its <Rob> is late
  int silence_ms = 100;  // no <Rob> for this long: the robot stopped sending (RSI off or stopped)
  bool realtime = true;  // try SCHED_FIFO and lock the thread's memory (reported, never required)
  int priority = 80;
};

// The newest <Rob>, as published for other threads (trivially copyable, fixed size).
inline constexpr size_t kMaxSlots = 160;
struct RobSample {
  uint64_t ipoc = 0;
  int64_t received_ns = 0;  // net::monotonicNs() when it arrived
  uint32_t session = 0;     // 1 for the first RSI session, +1 each time the robot starts sending again
  uint32_t count = 0;       // slots filled (the decoder's layout, at most kMaxSlots)
  std::array<double, kMaxSlots> values{};
};

// One cycle in brief, for plots and statistics: pushed to Link::samples() for every <Rob> decoded
// (trivially copyable, fixed size).
inline constexpr size_t kSampleSlots = 64;
struct LinkSample {
  uint64_t ipoc = 0;
  int64_t received_ns = 0;  // net::monotonicNs() when the <Rob> arrived
  int32_t answer_ns = -1;   // from its arrival to the <Sen> sent; -1: not answered (ONLYSEND, send failed)
  uint32_t session = 0;
  uint32_t count = 0;       // values filled: the decoder's first slots (layout order), at most kSampleSlots
  bool late = false;        // answered more than a cycle after the <Rob>
  std::array<double, kSampleSlots> values{};
};
using LinkSampleRing = net::SpscRing<LinkSample, 2048>;  // 8 s at 4 ms; ~1 MB, allocated once

struct LinkCounters {
  uint64_t received = 0;  // <Rob> datagrams decoded
  uint64_t answered = 0;  // <Sen> sent
  uint64_t rejected = 0;  // datagrams refused by the decoder (last_reason says why)
  uint64_t late = 0;      // answers sent more than a cycle after their <Rob> arrived
  uint64_t sessions = 0;  // RSI sessions seen
  uint64_t send_failures = 0;
};

class Link {
 public:
  using Callback = std::function<Correction(const RobDecoder& rob)>;

  Link(const EthernetConfig& config, LinkOptions options = {});
  ~Link();  // stop()
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;

  // Any thread, not real-time. The callback runs on the link's thread once per <Rob>: keep it
  // short, no allocation, no lock; it must be set before start().
  void setCallback(Callback callback);
  // Binds and starts the thread. Throws std::runtime_error saying what address and port could not
  // be bound and what to do.
  void start();
  void stop();
  uint16_t port() const { return port_; }  // the bound port (valid after start)
  const LinkOptions& options() const { return options_; }

  // Any thread, lock-free.
  bool latest(RobSample& out) const { return latest_.load(out) > 0; }
  bool receiving() const { return receiving_.load(std::memory_order_acquire); }
  LinkCounters counters() const;
  const char* lastReason() const { return last_reason_.load(std::memory_order_acquire); }
  // Every cycle's LinkSample, oldest first: exactly one consumer thread may pop (lock-free). When
  // it falls behind by a whole ring, new samples are dropped and counted (samples().dropped()).
  LinkSampleRing& samples() { return *samples_; }
  net::RealtimeStatus realtimeStatus() const;
  // Only inside the callback (the link's thread): the RSI session the datagram belongs to (1 for
  // the first; +1 each time the robot starts sending again after silence -- a new RSI_ON).
  uint32_t callbackSession() const { return session_; }
  // The decoder's slot of a SEND value (set-up), for RobSample::values and the callback.
  int slot(std::string_view element, std::string_view attribute = {}) const { return decoder_.slot(element, attribute); }
  // The encoder's slot of a RECEIVE value (set-up; -1 if the config has none), for setReceiveValue.
  int receiveSlot(std::string_view element, std::string_view attribute = {}) const {
    return encoder_.slot(element, attribute);
  }
  // Any thread, lock-free: a RECEIVE value that is not a correction (a digital output, Stop, a value
  // of your own) in every answer from the next one on. A correction from the callback overrides it.
  // Throws std::out_of_range for a slot the config does not have.
  void setReceiveValue(int slot, double value);

 private:
  void run();
  // Returns the answer's time after the <Rob> (ns), -1 if none was sent.
  int64_t answer(const net::Endpoint& to, int64_t received_ns);
  void takeReceiveValues();  // the link's thread: setReceiveValue's values into the encoder
  void newSession();

  const EthernetConfig config_;
  const LinkOptions options_;
  RobDecoder decoder_;
  SenEncoder encoder_;
  Callback callback_;
  std::array<int, 6> axis_slots_{}, cartesian_slots_{};
  std::array<double, 6> last_total_{};  // the last total correction sent (#RELATIVE)
  net::UdpSocket socket_;
  std::array<char, kMaxDatagramBytes + 1> datagram_{};  // one more: an oversized datagram shows as such
  uint16_t port_ = 0;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> receiving_{false};
  std::atomic<const char*> last_reason_{""};
  net::Seqlock<RobSample> latest_;
  std::unique_ptr<LinkSampleRing> samples_ = std::make_unique<LinkSampleRing>();
  net::Seqlock<LinkCounters> counters_;
  LinkCounters counting_;  // the thread's own copy, published after every datagram
  uint32_t session_ = 0;
  // setReceiveValue's values, taken into the encoder by the link's thread when `pending` is up.
  struct ReceiveValue {
    std::atomic<double> value{0};
    std::atomic<bool> set{false};
  };
  std::array<ReceiveValue, kMaxSlots> receive_values_{};
  std::atomic<bool> receive_pending_{false};
  net::RealtimeStatus status_;
  std::atomic<bool> status_ready_{false};
};

}  // namespace xmate::rsi
