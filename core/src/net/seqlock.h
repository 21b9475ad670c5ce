// SPDX-License-Identifier: Apache-2.0
// Latest-value publication without locks: one writer (the real-time thread) stores a value every
// cycle and never waits; readers copy the newest complete value, retrying if a write overlapped.
// The value is kept as 64-bit words copied with relaxed atomic loads and stores, so an overlapping
// read is a torn copy (detected by the sequence number and retried), never a data race.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace xmate::net {

template <class T>
class Seqlock {
  static_assert(std::is_trivially_copyable_v<T>, "Seqlock holds trivially copyable values");
  static_assert(std::atomic_ref<uint64_t>::is_always_lock_free, "Seqlock needs lock-free 64-bit atomics");

 public:
  // Writer only. Never blocks.
  void store(const T& value) {
    const uint64_t s = seq_.load(std::memory_order_relaxed);
    seq_.store(s + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    copyIn(value);
    std::atomic_thread_fence(std::memory_order_release);
    seq_.store(s + 2, std::memory_order_release);
  }

  // Any reader. Returns the number of stores so far (0 = nothing stored yet).
  uint64_t load(T& out) const {
    for (;;) {
      const uint64_t before = seq_.load(std::memory_order_acquire);
      if (before & 1) continue;  // a write is in progress
      copyOut(out);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (seq_.load(std::memory_order_relaxed) == before) return before / 2;
    }
  }

  uint64_t version() const { return seq_.load(std::memory_order_acquire) / 2; }

 private:
  static constexpr size_t kWords = (sizeof(T) + sizeof(uint64_t) - 1) / sizeof(uint64_t);

  // Word by word, each word a relaxed atomic load or store on buf_ (the value's own bytes are
  // moved with memcpy of at most one word: T need not be a whole number of words). The fences in
  // store() and load() order these against the sequence number. No lock, no allocation.
  void copyIn(const T& v) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&v);
    for (size_t i = 0; i < kWords; ++i) {
      uint64_t word = 0;
      std::memcpy(&word, bytes + i * sizeof word, chunk(i));
      std::atomic_ref<uint64_t>(buf_[i]).store(word, std::memory_order_relaxed);
    }
  }
  void copyOut(T& v) const {
    auto* bytes = reinterpret_cast<unsigned char*>(&v);
    for (size_t i = 0; i < kWords; ++i) {
      const uint64_t word = std::atomic_ref<uint64_t>(buf_[i]).load(std::memory_order_relaxed);
      std::memcpy(bytes + i * sizeof word, &word, chunk(i));
    }
  }
  // Bytes of T in word i (a full word except, perhaps, the last).
  static constexpr size_t chunk(size_t i) {
    return i + 1 < kWords ? sizeof(uint64_t) : sizeof(T) - i * sizeof(uint64_t);
  }

  std::atomic<uint64_t> seq_{0};
  alignas(std::atomic_ref<uint64_t>::required_alignment) mutable uint64_t buf_[kWords] = {};
};

}  // namespace xmate::net
