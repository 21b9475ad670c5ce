// SPDX-License-Identifier: Apache-2.0
// Latest-value publication without locks: one writer (the real-time thread) stores a value every
// cycle and never waits; readers copy the newest complete value, retrying if a write overlapped.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace xmate::net {

template <class T>
class Seqlock {
  static_assert(std::is_trivially_copyable_v<T>, "Seqlock holds trivially copyable values");

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
  // Byte-wise copies through volatile-free memcpy on an atomic-fenced buffer: the data race on
  // buf_ is benign by construction (torn reads are detected by the sequence number).
  void copyIn(const T& v) { std::memcpy(buf_, &v, sizeof(T)); }
  void copyOut(T& v) const { std::memcpy(&v, buf_, sizeof(T)); }

  std::atomic<uint64_t> seq_{0};
  alignas(alignof(T)) unsigned char buf_[sizeof(T)];
};

}  // namespace xmate::net
