// SPDX-License-Identifier: Apache-2.0
// JobWorker: the queue-and-thread behind the Session's command and motion workers (job_worker.h).
#include "session/job_worker.h"

#include "net/realtime.h"

namespace rci::ui {

JobWorker::JobWorker(const char* thread_name, std::function<void()> idle, std::chrono::milliseconds idle_period) {
  // Hand-off: the thread gets its own reference to the shared state, the idle job by value.
  thread_ = std::thread([state = state_, idle = std::move(idle), idle_period, thread_name] {
    loop(state, idle, idle_period, thread_name);
  });
}

JobWorker::~JobWorker() { stop(kDestructorWait); }

void JobWorker::post(std::function<void()> job, std::function<void()> dropped) {
  {
    // Hand-off: the job queue, guarded by State::mutex, signalled by State::wake.
    std::unique_lock lock(state_->mutex);
    if (state_->quit) {
      lock.unlock();
      if (dropped) dropped();
      return;
    }
    state_->jobs.push_back({std::move(job), std::move(dropped)});
  }
  state_->wake.notify_one();
}

bool JobWorker::busy() const {
  std::lock_guard lock(state_->mutex);
  return state_->running;
}

bool JobWorker::waitIdle(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(state_->mutex);
  return state_->done.wait_for(lock, timeout, [this] {
    return state_->ended || (!state_->running && state_->jobs.empty());
  });
}

bool JobWorker::stop(std::chrono::milliseconds timeout) {
  std::deque<Queued> discarded;
  bool finished = false;
  {
    std::unique_lock lock(state_->mutex);
    state_->quit = true;
    discarded.swap(state_->jobs);
    state_->wake.notify_one();
    finished = state_->done.wait_for(lock, timeout, [this] { return state_->ended; });
  }
  for (Queued& q : discarded)
    if (q.dropped) q.dropped();
  if (!thread_.joinable()) return true;
  if (finished) {
    thread_.join();
    return true;
  }
  thread_.detach();  // it still holds State; whatever its job holds is the caller's to keep alive
  return false;
}

void JobWorker::loop(const std::shared_ptr<State>& state, const std::function<void()>& idle,
                     std::chrono::milliseconds idle_period, const char* name) {
  xmate::net::nameThisThread(name);
  std::unique_lock lock(state->mutex);
  auto ready = [&] { return state->quit || !state->jobs.empty(); };
  for (;;) {
    if (idle) {
      state->wake.wait_for(lock, idle_period, ready);
    } else {
      state->wake.wait(lock, ready);
    }
    if (state->quit) break;
    if (!state->jobs.empty()) {
      Queued next = std::move(state->jobs.front());
      state->jobs.pop_front();
      state->running = true;
      lock.unlock();
      next.job();
      next = {};  // release what the job captured before reporting it done
      lock.lock();
      state->running = false;
      state->done.notify_all();
      if (!state->jobs.empty() || state->quit) continue;  // drain the queue before the next idle poll
    }
    if (idle) {
      lock.unlock();
      idle();
      lock.lock();
    }
  }
  state->ended = true;
  state->done.notify_all();
}

}  // namespace rci::ui
