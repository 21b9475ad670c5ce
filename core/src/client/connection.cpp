// SPDX-License-Identifier: Apache-2.0
// client::Connection on the caller's side: opening and closing the session (TCP, UDP, the
// real-time thread, the Connect handshake), TCP requests, waiting for states, and Control() runs.
#include "client/connection.h"

#include <cmath>
#include <cstdio>
#include <thread>

#include "client/connection_rt.h"
#include "net/clock.h"

namespace xmate::client {
namespace {

void logToStderr(const std::string& line) { std::fprintf(stderr, "rci: %s\n", line.c_str()); }

// "192.168.0.7:40211" from the busy ConnectResponse (a simulator extension, docs/protocol.md).
std::string holderText(const protocol::ConnectResponse& r) {
  if (!r.has_holder) return "another client";
  const auto& ip = r.holder_ip;
  return std::to_string(ip[0]) + "." + std::to_string(ip[1]) + "." + std::to_string(ip[2]) + "." +
         std::to_string(ip[3]) + ":" + std::to_string(r.holder_port);
}

// The UDP socket's kernel buffers: room for ~50 states, so a short stall of the real-time thread
// loses nothing, while a long one does not queue seconds of stale states.
constexpr int kUdpReceiveBufferBytes = 64 * 1024;
constexpr int kUdpSendBufferBytes = 64 * 1024;

}  // namespace

Connection::Connection(const std::string& ip, uint16_t port, XmateType type, SessionOptions options)
    : ip_(ip == "localhost" ? "127.0.0.1" : ip),
      port_(port),
      type_(type),
      options_(std::move(options)),
      rt_(std::make_unique<Realtime>()),
      samples_(std::make_unique<SampleRing>()) {
  net::makeEndpoint(ip_, port_);  // throws std::invalid_argument for a malformed address, before any I/O
}

Connection::~Connection() { close(); }

bool Connection::isOpen() const { return tcp_.isOpen() && rt_running_.load(); }

void Connection::open() {
  std::lock_guard lock(lifecycle_);
  openLocked();
}

void Connection::ensureOpen() {
  std::lock_guard lock(lifecycle_);
  if (isOpen()) return;
  if (ever_opened_.load())
    throw NetworkException("the session with the controller at " + ip_ + ":" + std::to_string(port_) +
                           " was lost or closed; it is not re-opened behind your back: call reconnect() "
                           "(or connect()) to open a new one");
  openLocked();
}

void Connection::openLocked() {
  if (isOpen()) return;
  closeLocked();  // leftovers of a broken session
  const net::Endpoint controller = net::makeEndpoint(ip_, port_);
  tcp_.open(controller, options_.timeouts.connect_ms);
  try {
    Realtime& rt = *rt_;
    const std::string local_ip = [&] {
      const std::string s = tcp_.local().toString();
      return s.substr(0, s.rfind(':'));
    }();
    rt.udp.bind(local_ip, 0);
    rt.udp.setBufferSizes(kUdpReceiveBufferBytes, kUdpSendBufferBytes);
    udp_port_ = rt.udp.localPort();
    rt.controller = controller;
    startRealtimeThread();
    handshake();
    // A new session has no motion started, and the limits sent to an earlier one may not hold for
    // it (a restarted controller starts with its own): they are checked again once sent again.
    updateRemembered([](Remembered& r) {
      r.move_armed = false;
      r.limits = MotionLimits{};
    });
    ever_opened_.store(true);
  } catch (const XmateException&) {
    closeLocked();
    throw;
  } catch (const std::exception& e) {
    closeLocked();
    throw NetworkException(std::string("connect: cannot set up the real-time exchange: ") + e.what());
  }
}

void Connection::close() {
  std::lock_guard lock(lifecycle_);
  closeLocked();
}

void Connection::closeLocked() {
  stopRealtimeThread();
  tcp_.close();
  rt_->udp.close();
  udp_port_ = 0;
}

void Connection::startRealtimeThread() {
  Realtime& rt = *rt_;
  rt.dof = type_ == XMATE3 || type_ == XMATE7 ? 6 : 7;
  rt.session_start_ns = net::monotonicNs();
  rt.silence_limit_ns = int64_t(options_.timeouts.control_silence_ms) * 1'000'000;
  rt.try_realtime = options_.realtime;
  rt.realtime_priority = options_.realtime_priority;
  rt.samples = samples_.get();
  rt.stop.store(false);
  rt.started.store(0);
  rt.have_state = false;
  rt.run_active = false;
  rt.last_id = 0;
  rt.counters = {};
  rt.period_stats.reset();
  rt.cost_stats.reset();
  rt.wrong_length_count.store(0);
  rt.hold_kind.store(0);
  rt.last_answered_id = 0;
  rt.latest_base.store(rt.latest.version());
  try {
    thread_ = std::thread(runRealtimeThread, std::ref(rt));
  } catch (const std::system_error& e) {
    throw NetworkException(std::string("connect: cannot start the real-time thread: ") + e.what());
  }
  rt.started.wait(0, std::memory_order_acquire);  // hand-off: atomic flag; status is written before it
  {
    std::lock_guard status_lock(status_mutex_);
    status_ = rt.status;
  }
  rt_running_.store(true);
  if (!rt.status.fifo || !rt.status.memory_locked) {
    const auto& log = options_.log ? options_.log : logToStderr;
    log("the real-time thread runs with " + rt.status.describe() +
        "; packets may be lost under load (see `rci-cli doctor`)");
  }
}

void Connection::stopRealtimeThread() {
  if (!thread_.joinable()) return;
  rt_->stop.store(true, std::memory_order_release);
  thread_.join();
  rt_running_.store(false);
  {
    std::lock_guard status_lock(status_mutex_);
    status_ = {};
  }
  // A run armed after the thread's last look ends here, as the thread would have ended it.
  finishArmedRunAsClosed(*rt_);
}

void Connection::handshake() {
  protocol::ConnectRequest request;
  request.udp_port = udp_port_.load();
  const auto payload = this->request("connect", request, options_.timeouts.connect_ms);
  protocol::ConnectResponse response;
  if (protocol::decodePayload(payload.data(), payload.size(), response) != protocol::DecodeStatus::kOk)
    throw ProtocolException("connect: the controller's ConnectResponse is " + std::to_string(payload.size()) +
                            " bytes, not 5; it speaks another protocol version");
  if (response.status == uint8_t(protocol::ConnectStatus::kBusy))
    throw TcpException("connect: the controller at " + ip_ + ":" + std::to_string(port_) +
                       " refused the session: the controller's session is held by " + holderText(response) +
                       " (another program is connected); close that program or wait until its session ends");
  if (response.status == uint8_t(protocol::ConnectStatus::kIncompatibleLibraryVersion))
    throw ProtocolException(
        "connect: the controller at " + ip_ + ":" + std::to_string(port_) +
        " refused the session: incompatible library version. This client speaks the RCI wire format of "
        "client SDK 1.4 (RobotState 1247 bytes, RobotCommand 290 bytes); use a client library that "
        "matches the controller's RCI version, or update the controller");
  if (response.status != uint8_t(protocol::ConnectStatus::kSuccess))
    throw ProtocolException("connect: unknown ConnectResponse status " + std::to_string(response.status));
}

std::vector<uint8_t> Connection::requestFrame(const char* call, const std::function<protocol::Frame(uint32_t)>& encode,
                                              protocol::Command command, int timeout_ms) {
  try {
    return tcp_.exchange(call, encode, command, timeout_ms);
  } catch (const TcpException&) {
    // The session broke: no stream without it. If another thread is opening or closing right now,
    // that thread deals with the real-time thread.
    if (!tcp_.isOpen()) {
      std::unique_lock lock(lifecycle_, std::try_to_lock);
      if (lock.owns_lock() && !tcp_.isOpen()) stopRealtimeThread();
    }
    throw;
  }
}

RCI::robot::RobotState Connection::waitForState() {
  Realtime& rt = *rt_;
  if (!rt_running_.load()) throw UdpException("receiveRobotState: no session with the controller; call connect()");
  const uint64_t version = rt.latest.version();
  const uint64_t wrong = rt.wrong_length_count.load(std::memory_order_acquire);
  const int64_t deadline = net::monotonicNs() + int64_t(options_.timeouts.state_ms) * 1'000'000;
  RCI::robot::RobotState state;
  for (;;) {
    if (rt.latest.version() != version) {
      rt.latest.load(state);
      std::lock_guard lock(handed_out_mutex_);
      handed_out_ = state;
      return state;
    }
    if (rt.wrong_length_count.load(std::memory_order_acquire) != wrong)
      throw UdpException("receiveRobotState: the controller sent a state datagram of " +
                         std::to_string(rt.last_wrong_length.load()) + " bytes instead of " +
                         std::to_string(protocol::kRobotStateSize) +
                         ": it speaks another RCI protocol version; use a matching client library");
    if (net::monotonicNs() > deadline)
      throw UdpException("receiveRobotState: no state from " + ip_ + " for " +
                         std::to_string(options_.timeouts.state_ms) + " ms on UDP port " +
                         std::to_string(udp_port_.load()) + "; check that no firewall blocks UDP and that the "
                         "controller is in RCI mode");
    std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

bool Connection::latestState(RCI::robot::RobotState& out) const {
  return rt_->latest.load(out) > rt_->latest_base.load();
}

Standstill Connection::standstill() const {
  Standstill s;
  rt_->standstill.load(s);
  return s;
}

StandstillWait Connection::awaitStandstill(const char* call) {
  const int64_t deadline = net::monotonicNs() + int64_t(kStandstillWaitMs) * 1'000'000;
  RCI::robot::RobotState first;
  bool waited = false;
  for (;;) {
    RCI::robot::RobotState newest;
    if (!latestState(newest)) return {};  // nothing known yet: the controller decides
    if (!waited) first = newest;
    const Standstill s = standstill();
    const bool late = net::monotonicNs() > deadline;
    if (!settling(s, newest) || (late && s.at_rest))
      return travelSince(waited ? &first : nullptr, newest);
    waited = true;
    if (late)
      throw MotionException(std::string(call) + ": " + stillStoppingText(s) +
                            "; wait until it stands still, then try again");
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

StandstillWait Connection::travelSince(const RCI::robot::RobotState* wait_began,
                                       const RCI::robot::RobotState& newest) const {
  StandstillWait travel = wait_began ? travelBetween(*wait_began, newest, rt_->dof) : StandstillWait{};
  std::lock_guard lock(handed_out_mutex_);
  if (!handed_out_ || handed_out_->message_id > newest.message_id) return travel;
  bool moving = false;
  for (int i = 0; i < rt_->dof; ++i)
    moving |= std::fmax(std::fabs(handed_out_->dq_m[size_t(i)]), std::fabs(handed_out_->dq_c[size_t(i)])) >= kStillSpeed;
  if (!moving) return travel;
  const StandstillWait since_read = travelBetween(*handed_out_, newest, rt_->dof);
  travel.joint_travel = std::fmax(travel.joint_travel, since_read.joint_travel);
  travel.tcp_travel = std::fmax(travel.tcp_travel, since_read.tcp_travel);
  travel.rotation_travel = std::fmax(travel.rotation_travel, since_read.rotation_travel);
  return travel;
}

SessionTiming Connection::timing() const {
  SessionTiming t;
  rt_->timing.load(t);
  return t;
}

net::RealtimeStatus Connection::realtimeStatus() const {
  std::lock_guard lock(status_mutex_);
  return status_;  // a copy taken when the thread reported `started`
}

void Connection::beginMotionHold(ControlKind kind) {
  // Hand-off: two atomics; the thread reads the time after seeing the kind (acquire).
  rt_->motion_requested_ns.store(net::monotonicNs(), std::memory_order_relaxed);
  rt_->hold_kind.store(uint32_t(kind) + 1, std::memory_order_release);
}

void Connection::endMotionHold() { rt_->hold_kind.store(0, std::memory_order_release); }

ControlResult Connection::runControl(const JointControl& callback, MissedStates missed) {
  return runControl(ControlKind::kJoint, &callback, missed);
}
ControlResult Connection::runControl(const CartesianControl& callback, MissedStates missed) {
  return runControl(ControlKind::kCartesian, &callback, missed);
}
ControlResult Connection::runControl(const TorqueControl& callback, MissedStates missed) {
  return runControl(ControlKind::kTorque, &callback, missed);
}

ControlResult Connection::runControl(ControlKind kind, const void* callback, MissedStates missed) {
  Realtime& rt = *rt_;
  ControlResult result;
  result.kind = kind;
  if (!rt_running_.load()) {
    result.outcome = ControlOutcome::kSessionClosed;
    return result;
  }
  // Hand-off: request fields, then kIdle -> kArmed (compare-and-swap, release); the thread answers
  // with kDone (see RunState).
  uint32_t idle = kRunIdle;
  if (rt.run_state.load() != kRunIdle)
    throw InvalidOperationException("Control(): another Control() run is active on this session");
  rt.kind = kind;
  rt.callback = callback;
  rt.replay_missed = missed == MissedStates::kReplay;
  if (!rt.run_state.compare_exchange_strong(idle, kRunArmed))
    throw InvalidOperationException("Control(): another Control() run is active on this session");
  endMotionHold();  // the run answers from now on (the thread checks the run first)
  // Closed meanwhile (the thread may have looked for a run before it was armed): end it here. If
  // close() is still joining, its own finishArmedRunAsClosed does it; exactly one of the two wins.
  if (!rt_running_.load()) {
    std::lock_guard lock(lifecycle_);  // no thread starts or stops while we look
    if (!rt_running_.load()) finishArmedRunAsClosed(rt);
  }
  for (uint32_t s = rt.run_state.load(std::memory_order_acquire); s != kRunDone;
       s = rt.run_state.load(std::memory_order_acquire))
    rt.run_state.wait(s, std::memory_order_acquire);

  result.outcome = rt.outcome;
  result.last_state = rt.last_state;
  result.cycles = rt.cycles;
  result.exception = rt.exception;
  result.fault = rt.fault;
  result.wrong_length = rt.wrong_length;
  result.longest_stall_ms = double(rt.longest_stall_ns) * 1e-6;
  result.stall_message_id = rt.stall_message_id;
  result.states_skipped = rt.states_skipped;
  result.states_missed = rt.states_missed_in_run;
  result.longest_miss = rt.longest_miss;
  result.miss_message_id = rt.miss_message_id;
  result.states_replayed = rt.states_replayed;
  const uint64_t count = std::min<uint64_t>(rt.log_written, kControlLogLength);
  result.log.reserve(count);
  for (uint64_t i = rt.log_written - count; i < rt.log_written; ++i) result.log.push_back(rt.log[i % kLogCapacity]);
  rt.exception = nullptr;
  rt.callback = nullptr;
  rt.run_state.store(kRunIdle, std::memory_order_release);
  return result;
}

}  // namespace xmate::client
