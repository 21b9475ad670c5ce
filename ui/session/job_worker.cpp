// SPDX-License-Identifier: Apache-2.0
// JobWorker: the queue-and-thread behind the Session's command and motion workers.
#include "session/job_worker.h"

#include "net/realtime.h"

namespace rci::ui {

JobWorker::JobWorker(const char* thread_name, std::function<void()> idle, std::chrono::milliseconds idle_period)
    : idle_(std::move(idle)), idle_period_(idle_period), name_(thread_name) {
  thread_ = std::thread([this] { loop(); });
}

JobWorker::~JobWorker() { stop(); }

void JobWorker::post(std::function<void()> job) {
  {
    // Hand-off: the job queue, guarded by mutex_, signalled by wake_.
    std::lock_guard lock(mutex_);
    if (quit_) return;
    jobs_.push_back(std::move(job));
  }
  wake_.notify_one();
}

void JobWorker::stop() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    jobs_.clear();
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

// Waits until a job is queued, the idle period passed, or stop() was called. Returns false on stop.
bool JobWorker::waitForWork(std::unique_lock<std::mutex>& lock) {
  auto ready = [this] { return quit_ || !jobs_.empty(); };
  if (idle_) {
    wake_.wait_for(lock, idle_period_, ready);
  } else {
    wake_.wait(lock, ready);
  }
  return !quit_;
}

void JobWorker::loop() {
  xmate::net::nameThisThread(name_);
  std::unique_lock lock(mutex_);
  while (waitForWork(lock)) {
    if (!jobs_.empty()) {
      auto job = std::move(jobs_.front());
      jobs_.pop_front();
      lock.unlock();
      job();
      lock.lock();
      if (!jobs_.empty() || quit_) continue;  // drain the queue before the next idle poll
    }
    if (idle_ && !quit_) {
      lock.unlock();
      idle_();
      lock.lock();
    }
  }
}

}  // namespace rci::ui
