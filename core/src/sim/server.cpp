// SPDX-License-Identifier: Apache-2.0
// sim::Server: start/stop/kill, the job queue that hands work to the cycle thread, the public scene
// and fault calls, and the published status. The threads themselves live in server_cycle.cpp and
// server_session.cpp.
#include "sim/server.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>

#include "sim/server_impl.h"

namespace xmate::sim {

const char* toString(ClockMode clock) {
  return clock == ClockMode::kLockStep ? "lock-step clock" : "real-time clock";
}

// ---- The job queue ------------------------------------------------------------------------------

void runOnCycleThread(Server::Impl& s, const std::function<void()>& job) {
  std::unique_lock lock(s.jobs_mutex);
  if (!s.cycle_alive) {  // nobody else touches the cycle thread's data now: run it here
    job();
    publishSnapshot(s);
    return;
  }
  std::exception_ptr error;
  s.jobs.push_back([&] {
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
  });
  const uint64_t ticket = ++s.jobs_posted;
  s.jobs_cv.wait(lock, [&] { return s.jobs_done >= ticket; });
  if (error) std::rethrow_exception(error);
}

void runQueuedJobs(Server::Impl& s) {
  for (;;) {
    std::function<void()> job;
    {
      std::lock_guard lock(s.jobs_mutex);
      if (s.jobs.empty()) return;
      job = std::move(s.jobs.front());
      s.jobs.pop_front();
    }
    try {
      job();
    } catch (const std::exception& e) {
      s.log(std::string("internal error while applying a request: ") + e.what());
    }
    publishSnapshot(s);  // the caller may look at status() as soon as it returns
    {
      std::lock_guard lock(s.jobs_mutex);
      ++s.jobs_done;
    }
    s.jobs_cv.notify_all();
  }
}

// ---- Snapshot and scene --------------------------------------------------------------------------

void publishSnapshot(Server::Impl& s) {
  std::lock_guard lock(s.snapshot_mutex);
  s.snapshot.streaming = s.streaming;
  s.snapshot.rebooting = s.rebooting;
  s.snapshot.pending = pendingFaults(s.state_faults, s.command_faults);
  s.snapshot.state_loss = s.state_faults.loss.config;
  s.snapshot.counters = s.counters;
  if (s.controller) {
    s.snapshot.sim = s.controller->status();
    s.snapshot.state = s.controller->state();
  }
}

void applyScene(Server::Impl& s) {
  if (!s.controller) return;
  Controller& c = *s.controller;
  c.setExternalWrench(s.scene.wrench);
  c.setEmergencyStop(s.scene.estop);
  c.setGuardStop(s.scene.gstop);
  for (int i = 0; i < 6; ++i) c.setDigitalInput(i, s.scene.digital_in[size_t(i)]);
  c.setDoToDiLoopback(s.scene.loopback);
  if (const auto& p = s.scene.actual_payload) {
    try {
      c.setActualPayload(p->mass, p->center, p->inertia);
    } catch (const std::exception& e) {
      s.log(std::string("the actual payload could not be applied: ") + e.what());
    }
  }
}

// ---- Lifecycle -------------------------------------------------------------------------------------

namespace {

std::string formatNumber(double value) {
  std::ostringstream o;
  o << value;
  return o.str();
}

void setClientText(Server::Impl& s, const std::string& text) {
  std::lock_guard lock(s.snapshot_mutex);
  s.client_text = text;
}

// Opens both sockets; the TCP port is the previous one after a stop() so clients find it again.
void bindSockets(Server::Impl& s) {
  const uint16_t wanted = s.bound_port != 0 ? s.bound_port.load() : s.config.port;
  try {
    s.listener.listen(s.config.bind_ip, wanted);
    s.udp.bind(s.config.bind_ip, 0);
  } catch (const std::exception& e) {
    s.listener.close();
    throw std::runtime_error(std::string("simulated controller cannot start: ") + e.what() +
                             " -- choose another port (0 picks a free one) or stop the other program");
  }
  s.udp.setBufferSizes(1 << 20, 1 << 20);
  s.bound_port = s.listener.localPort();
}

void resetRunState(Server::Impl& s) {
  s.stopping = false;
  s.killed = false;
  s.rebooting = false;
  s.streaming = false;
  s.state_faults = StateFaults{};
  s.command_faults = CommandFaults{};
  s.counters = ServerCounters{};
  s.clients_refused = 0;
  s.sessions_dropped = 0;
  s.cycle_started = false;
  setClientText(s, "");
  std::lock_guard lock(s.snapshot_mutex);
  s.last_refusal.clear();
}

void joinThreads(Server::Impl& s) {
  if (s.cycle_thread.joinable()) s.cycle_thread.join();
  if (s.tcp_thread.joinable()) s.tcp_thread.join();
}

}  // namespace

Server::Server(ServerConfig config) : impl_(std::make_unique<Impl>(std::move(config))) {
  impl_->scene.loopback = impl_->config.sim.do_to_di_loopback;
}

Server::~Server() { stop(); }

void Server::start() {
  Impl& s = *impl_;
  std::lock_guard life(s.lifecycle_mutex);
  if (s.running) throw std::logic_error("sim::Server::start: already running (call stop() first)");
  {
    std::lock_guard lock(s.jobs_mutex);  // the cycle thread is not alive: its data is ours
    resetRunState(s);
    s.controller = std::make_unique<Controller>(s.config.sim);
    applyScene(s);
    bindSockets(s);
    publishSnapshot(s);
    s.cycle_alive = true;
  }
  s.cycle_thread = std::thread([&s] { runCycleThread(s); });
  {
    std::unique_lock lock(s.startup_mutex);
    s.startup_cv.wait(lock, [&] { return s.cycle_started; });
  }
  s.tcp_thread = std::thread([&s] { runTcpThread(s); });
  s.running = true;
  s.log(std::string("listening on ") + s.config.bind_ip + ":" + std::to_string(s.bound_port) + ", " +
        toString(s.config.clock));
}

void Server::stop() {
  Impl& s = *impl_;
  std::lock_guard life(s.lifecycle_mutex);
  if (!s.running) return;
  s.stopping = true;
  joinThreads(s);
  s.listener.close();
  s.udp.close();
  s.running = false;
  std::lock_guard lock(s.jobs_mutex);
  s.streaming = false;
  publishSnapshot(s);
}

bool Server::running() const { return impl_->running; }

uint16_t Server::port() const { return impl_->bound_port; }

const ServerConfig& Server::config() const { return impl_->config; }

void Server::kill() {
  Impl& s = *impl_;
  std::lock_guard life(s.lifecycle_mutex);
  if (!s.running || s.killed) return;
  s.killed = true;
  joinThreads(s);  // the cycle stops at once; the TCP thread drops the session and the listener
  s.udp.close();
  std::lock_guard lock(s.jobs_mutex);
  s.streaming = false;
  publishSnapshot(s);
  s.log("killed: no state stream, TCP closed, connections refused until restarted");
}

// ---- Scene ----------------------------------------------------------------------------------------

void Server::setExternalWrench(const std::array<double, 6>& wrench) {
  for (size_t i = 0; i < wrench.size(); ++i)
    if (!std::isfinite(wrench[i]))
      throw std::invalid_argument("setExternalWrench: element " + std::to_string(i) + " is not a finite number");
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    s.scene.wrench = wrench;
    if (s.controller) s.controller->setExternalWrench(wrench);
  });
}

void Server::setEmergencyStop(bool pressed) {
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    s.scene.estop = pressed;
    if (s.controller) s.controller->setEmergencyStop(pressed);
  });
}

void Server::setGuardStop(bool active) {
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    s.scene.gstop = active;
    if (s.controller) s.controller->setGuardStop(active);
  });
}

void Server::setDigitalInput(int index, bool level) {
  if (index < 0 || index > 5)
    throw std::invalid_argument("setDigitalInput: index must be 0..5 (DI0_0..DI1_1), got " + std::to_string(index));
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    s.scene.digital_in[size_t(index)] = level;
    if (s.controller) s.controller->setDigitalInput(index, level);
  });
}

void Server::setDoToDiLoopback(bool on) {
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    s.scene.loopback = on;
    if (s.controller) s.controller->setDoToDiLoopback(on);
  });
}

void Server::setActualPayload(double mass, const std::array<double, 3>& center, const std::array<double, 9>& inertia) {
  if (!std::isfinite(mass) || mass < 0)
    throw std::invalid_argument("setActualPayload: the mass must be a finite number >= 0 kg, got " + formatNumber(mass));
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    if (s.controller) s.controller->setActualPayload(mass, center, inertia);  // validates the rest
    s.scene.actual_payload = Scene::Payload{mass, center, inertia};
  });
}

void Server::followConfiguredLoad() {
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    if (s.controller) s.controller->followConfiguredLoad();
    s.scene.actual_payload.reset();
  });
}

void Server::placeArm(const std::array<double, 7>& q) {
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    if (s.controller) s.controller->placeArm(q);  // validates
  });
}

// ---- Packet faults --------------------------------------------------------------------------------

namespace {

// Adds to a countdown without passing the upper bound.
void addCount(int& counter, int count) { counter = std::min(counter + count, kMaxFaultCount); }

}  // namespace

void Server::dropStates(int count) {
  checkFaultCount("dropStates", count);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { addCount(s.state_faults.drop, count); });
}

void Server::dropCommands(int count) {
  checkFaultCount("dropCommands", count);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { addCount(s.command_faults.drop, count); });
}

void Server::delayCommands(int count, int delay_ms) {
  checkFaultCount("delayCommands", count);
  checkFaultDelay("delayCommands", delay_ms);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] {
    addCount(s.command_faults.delay, count);
    s.command_faults.delay_ms = delay_ms;
  });
}

void Server::reorderStates(int count) {
  checkFaultCount("reorderStates", count);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { addCount(s.state_faults.reorder, count + count % 2); });
}

void Server::corruptStates(int count) {
  checkFaultCount("corruptStates", count);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { addCount(s.state_faults.corrupt, count); });
}

void Server::sendWrongLengthStates(int count) {
  checkFaultCount("sendWrongLengthStates", count);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { addCount(s.state_faults.wrong_length, count); });
}

void Server::setStateLoss(const StateLoss& loss) {
  checkStateLoss("setStateLoss", loss);
  Impl& s = *impl_;
  runOnCycleThread(s, [&] { startStateLoss(s.state_faults.loss, loss); });
}

// ---- Observation ------------------------------------------------------------------------------------

ServerStatus Server::status() const {
  const Impl& s = *impl_;
  ServerStatus st;
  st.running = s.running;
  std::lock_guard lock(s.snapshot_mutex);
  st.killed = s.killed;
  st.rebooting = s.snapshot.rebooting;
  st.session = s.session_open;
  st.streaming = s.snapshot.streaming;
  st.port = s.bound_port;
  st.client = s.client_text;
  st.clock = s.config.clock;
  st.realtime = s.realtime_text;
  st.last_refusal = s.last_refusal;
  st.pending = s.snapshot.pending;
  st.state_loss = s.snapshot.state_loss;
  st.counters = s.snapshot.counters;
  st.counters.clients_refused = s.clients_refused;
  st.counters.sessions_dropped = s.sessions_dropped;
  st.sim = s.snapshot.sim;
  st.message_id = s.snapshot.state.message_id;
  st.awaiting_answer_to = s.snapshot.awaiting_answer_to;
  return st;
}

RCI::robot::RobotState Server::latestState() const {
  std::lock_guard lock(impl_->snapshot_mutex);
  return impl_->snapshot.state;
}

ServerConfig embeddedConfig(XmateType type, ClockMode clock) {
  ServerConfig config;
  config.bind_ip = "127.0.0.1";
  config.port = 0;
  config.clock = clock;
  config.sim.type = type;
  return config;
}

std::unique_ptr<Server> startEmbedded(ServerConfig config) {
  auto server = std::make_unique<Server>(std::move(config));
  try {
    server->start();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("The built-in simulator could not start: ") + e.what() +
                             ". Check that the robot descriptions are installed (share/rci) or set "
                             "RCI_DATA_DIR to the source tree.");
  }
  return server;
}

}  // namespace xmate::sim
