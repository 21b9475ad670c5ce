// SPDX-License-Identifier: Apache-2.0
// JobWorker: one std::thread that runs queued jobs in order and, while idle, an optional periodic
// idle job (the Session's command and motion workers, docs/architecture.md, "Threads and hand-offs").
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace rci::ui {

class JobWorker {
 public:
  // idle runs on the worker whenever no job has run for idle_period (and after each job).
  // Pass an empty idle for a worker that only runs jobs.
  JobWorker(const char* thread_name, std::function<void()> idle = {},
            std::chrono::milliseconds idle_period = std::chrono::milliseconds(200));
  ~JobWorker();  // stop()s
  JobWorker(const JobWorker&) = delete;
  JobWorker& operator=(const JobWorker&) = delete;

  // Appends a job. Any thread.
  void post(std::function<void()> job);
  // Drops the jobs not yet started, lets the running one finish and joins the thread.
  void stop();

 private:
  void loop();
  bool waitForWork(std::unique_lock<std::mutex>& lock);

  std::function<void()> idle_;
  std::chrono::milliseconds idle_period_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> jobs_;
  bool quit_ = false;
  const char* name_;
  std::thread thread_;
};

}  // namespace rci::ui
