// SPDX-License-Identifier: Apache-2.0
// CPU burners: threads that keep the cores of a small machine busy while they exist, for stress tests
// and soaks of the real-time loop (what a loaded PC without a real-time kernel does to it). Header only.
#pragma once

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

namespace xmate::net {

class CpuBurners {
 public:
  // Starts `threads` threads at normal priority, each spinning on arithmetic until destroyed.
  explicit CpuBurners(int threads = 2) {
    for (int i = 0; i < threads; ++i) threads_.emplace_back([this] { burn(); });
  }
  ~CpuBurners() {
    stop_.store(true);
    for (std::thread& t : threads_) t.join();
  }
  CpuBurners(const CpuBurners&) = delete;
  CpuBurners& operator=(const CpuBurners&) = delete;

 private:
  void burn() const {
    volatile double x = 1.0;
    while (!stop_.load(std::memory_order_relaxed))
      for (int k = 0; k < 10000; ++k) x = std::sqrt(x + 1.0);
  }

  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

}  // namespace xmate::net
