// SPDX-License-Identifier: Apache-2.0
// Single-producer/single-consumer ring of fixed capacity: the lock-free hand-off from a real-time
// thread to a reader (docs/architecture.md, "Threads and hand-offs"). push() never blocks or
// allocates; when the ring is full the newest sample is dropped and counted, so the producer's
// timing never depends on the reader.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace xmate::net {

template <class T, size_t Capacity>
class SpscRing {
  static_assert(Capacity >= 2 && (Capacity & (Capacity - 1)) == 0, "Capacity must be a power of two");

 public:
  // Producer side. Returns false (and counts a drop) when full.
  bool push(const T& value) {
    const uint64_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_.load(std::memory_order_acquire) >= Capacity) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    slots_[head & (Capacity - 1)] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer side. Returns false when empty.
  bool pop(T& out) {
    const uint64_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    out = slots_[tail & (Capacity - 1)];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }

  // Consumer side: pops up to max items into out[]; returns how many.
  size_t popBatch(T* out, size_t max) {
    size_t n = 0;
    while (n < max && pop(out[n])) ++n;
    return n;
  }

  size_t size() const {
    return size_t(head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire));
  }
  uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }
  static constexpr size_t capacity() { return Capacity; }

 private:
  alignas(64) std::atomic<uint64_t> head_{0};
  alignas(64) std::atomic<uint64_t> tail_{0};
  alignas(64) std::atomic<uint64_t> dropped_{0};
  std::array<T, Capacity> slots_{};
};

}  // namespace xmate::net
