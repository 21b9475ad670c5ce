// SPDX-License-Identifier: Apache-2.0
// LossWatch (soak_losses.h): the gaps in the message_ids of the states the client received.
#include "soak/soak_losses.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

namespace rci_cli::soak {
namespace {

constexpr auto kPollInterval = std::chrono::milliseconds(2);  // the ring holds 4 s: plenty of margin
constexpr size_t kBatch = 256;

}  // namespace

LossWatch::LossWatch(xmate::client::Connection& session) : session_(session), thread_([this] { run(); }) {}

LossWatch::~LossWatch() {
  stop_.store(true);
  thread_.join();
}

void LossWatch::run() {
  std::vector<xmate::client::StateSample> batch(kBatch);
  while (!stop_.load()) {
    const size_t n = session_.samples().popBatch(batch.data(), batch.size());
    for (size_t i = 0; i < n; ++i) take(batch[i]);
    if (n < batch.size()) std::this_thread::sleep_for(kPollInterval);
  }
}

void LossWatch::take(const xmate::client::StateSample& sample) {
  // A sample older than the last by the session's clock comes from a new session: no gap to it.
  const bool same_session = last_time_ >= 0 && sample.time >= last_time_;
  if (same_session && sample.message_id > last_id_ + 1) {
    std::lock_guard lock(mutex_);
    gaps_.push_back({sample.message_id, sample.message_id - last_id_ - 1});
  }
  if (!same_session || sample.message_id > last_id_) last_id_ = sample.message_id;
  last_time_ = sample.time;
  newest_id_.store(last_id_);
}

Losses LossWatch::between(uint64_t after, uint64_t up_to) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (newest_id_.load() < up_to && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(kPollInterval);
  return sum(after, up_to);
}

Losses LossWatch::total() { return sum(0, UINT64_MAX); }

Losses LossWatch::sum(uint64_t after, uint64_t up_to) {
  Losses losses;
  std::lock_guard lock(mutex_);
  for (const Gap& gap : gaps_) {
    if (gap.end_id <= after || gap.end_id > up_to) continue;
    losses.states += gap.length;
    losses.longest = std::max(losses.longest, gap.length);
  }
  return losses;
}

}  // namespace rci_cli::soak
