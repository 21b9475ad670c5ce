// SPDX-License-Identifier: Apache-2.0
// JobWorker: one std::thread that runs queued jobs in order and, while idle, an optional periodic
// idle job (the Session's command and motion workers; docs/architecture.md, "Threads and hand-offs"). Stopping it
// never waits without bound: a job that does not end in time is abandoned with its thread.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace rci::ui {

class JobWorker {
 public:
  // idle runs on the worker whenever no job has run for idle_period (and after each job).
  // Pass an empty idle for a worker that only runs jobs.
  JobWorker(const char* thread_name, std::function<void()> idle = {},
            std::chrono::milliseconds idle_period = std::chrono::milliseconds(200));
  ~JobWorker();  // stop(kDestructorWait)
  JobWorker(const JobWorker&) = delete;
  JobWorker& operator=(const JobWorker&) = delete;

  static constexpr std::chrono::milliseconds kDestructorWait{5000};

  // Appends a job. dropped (optional) runs instead of the job, on the thread that calls stop(), when
  // stop() discards the job before it started -- so whoever waits for the job's end learns of it.
  // A job posted after stop() is dropped at once. Any thread.
  void post(std::function<void()> job, std::function<void()> dropped = {});
  // true while a job (not the idle job) runs. Any thread.
  bool busy() const;
  // Waits until no job runs and none is queued, at most `timeout`. true if idle. Any thread but the worker's.
  bool waitIdle(std::chrono::milliseconds timeout) const;
  // Drops the jobs not yet started (calling their `dropped`), waits at most `timeout` for the
  // running one to finish and joins the thread. If the job is still running then, the thread is
  // detached and left to finish on its own (its state stays alive), and stop() returns false. Safe
  // to call twice. Any thread but the worker's.
  bool stop(std::chrono::milliseconds timeout = kDestructorWait);

 private:
  struct Queued {
    std::function<void()> job, dropped;
  };
  // Shared with the thread, so that an abandoned thread never touches freed memory.
  struct State {
    mutable std::mutex mutex;
    std::condition_variable wake;          // jobs queued, quit
    mutable std::condition_variable done;  // a job finished, the loop ended
    std::deque<Queued> jobs;
    bool quit = false;
    bool running = false;  // a job is executing
    bool ended = false;    // the loop returned
  };
  static void loop(const std::shared_ptr<State>& state, const std::function<void()>& idle,
                   std::chrono::milliseconds idle_period, const char* name);

  std::shared_ptr<State> state_ = std::make_shared<State>();
  std::thread thread_;
};

}  // namespace rci::ui
