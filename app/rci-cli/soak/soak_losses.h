// SPDX-License-Identifier: Apache-2.0
// The soak's view of lost states: a thread that reads every state the client received (the session's
// sample ring; it must be the ring's only reader) and keeps each message_id gap, so the losses
// during one motion -- how many, the longest run -- can be asked for afterwards.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "client/connection.h"

namespace rci_cli::soak {

struct Losses {
  uint64_t states = 0;   // states that never arrived
  uint64_t longest = 0;  // the longest run of them
};

class LossWatch {
 public:
  explicit LossWatch(xmate::client::Connection& session);
  ~LossWatch();  // stops the thread
  LossWatch(const LossWatch&) = delete;
  LossWatch& operator=(const LossWatch&) = delete;

  // The losses whose gap ended after message_id `after` and at `up_to` or before. Waits (at most
  // a second) until the thread has read the stream up to `up_to`.
  Losses between(uint64_t after, uint64_t up_to);
  // Every loss seen so far.
  Losses total();

 private:
  struct Gap {
    uint64_t end_id;  // the first state that arrived after it
    uint64_t length;
  };
  void run();
  Losses sum(uint64_t after, uint64_t up_to);  // the gaps that ended in (after, up_to]
  void take(const xmate::client::StateSample& sample);

  xmate::client::Connection& session_;
  std::mutex mutex_;
  std::vector<Gap> gaps_;  // guarded by mutex_, in order of end_id
  std::atomic<uint64_t> newest_id_{0};
  uint64_t last_id_ = 0;     // the thread's own
  double last_time_ = -1;    // a sample's session time: it starts again with a new session
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace rci_cli::soak
