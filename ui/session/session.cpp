// SPDX-License-Identifier: Apache-2.0
// Session: opens and closes links on background threads, runs commands and motions on worker
// threads, and refreshes LiveState at 30 Hz on the GUI thread (session.h; docs/architecture.md,
// "Threads and hand-offs").
#include "session/session.h"

#include <algorithm>

#include <QElapsedTimer>
#include <QMetaObject>
#include <QTimer>

#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "arm/rci_arm.h"
#include "arm/rsi_arm.h"
#include "net/clock.h"
#include "session/session_link.h"

namespace rci::ui {
namespace {

// Runs a queued job on a worker thread: (true, "") or (false, what the exception said).
std::pair<bool, QString> runCatching(const std::function<void()>& job) {
  try {
    job();
    return {true, QString()};
  } catch (const std::exception& e) {
    return {false, QString::fromStdString(e.what())};
  }
}

const QString kNotConnected = QStringLiteral("not connected: connect to a robot or the simulator first");

constexpr int kTickMs = 33;            // ~30 Hz display rate
constexpr qint64 kSilenceLimitMs = 1000;  // no state for this long: the controller is gone

int64_t steadyNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Threads that open or tear down links; joined when done or at the latest by joinAll().
class BackgroundThreads {
 public:
  ~BackgroundThreads() { joinAll(); }
  void start(std::function<void()> work) {
    reapFinished();
    auto done = std::make_shared<std::atomic<bool>>(false);
    threads_.push_back({std::thread([work = std::move(work), done] {
                          work();
                          done->store(true);
                        }),
                        done});
  }
  void joinAll() {
    for (auto& entry : threads_) entry.thread.join();
    threads_.clear();
  }

 private:
  struct Entry {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  void reapFinished() {
    std::erase_if(threads_, [](Entry& entry) {
      if (!entry.done->load()) return false;
      entry.thread.join();
      return true;
    });
  }
  std::vector<Entry> threads_;
};

// An xMate's six signals as LiveState's bits (bit k = signal k).
uint64_t bitsOf(const std::array<bool, 6>& levels) {
  uint64_t bits = 0;
  for (size_t k = 0; k < levels.size(); ++k)
    if (levels[k]) bits |= uint64_t{1} << k;
  return bits;
}

// The KUKA simulator's outputs as the arm names them: bit k = output k of outputNames().
uint64_t simulatedOutputs(xmate::arm::RsiArm& arm, uint64_t digout) {
  uint64_t bits = 0;
  if (const xmate::rsi::DigitalIo* io = arm.digitalIo()) {
    const auto& outputs = io->map().outputs;
    for (size_t k = 0; k < outputs.size() && k < 64; ++k) {
      const int signal = outputs[k].signal;
      if (signal >= 1 && signal <= 64 && (digout >> (signal - 1)) & 1u) bits |= uint64_t{1} << k;
    }
  }
  return bits;
}

QString silenceReason(const SessionTarget& target) {
  if (target.kind == SessionTarget::Kind::kSimulator)
    return QStringLiteral("The built-in simulator stopped sending states and could not be reached again. "
                          "Connect again to start a fresh simulator.");
  return QStringLiteral("The controller at %1:%2 stopped answering and could not be reached again within 60 s. "
                        "Check that it is switched on and the network cable is plugged in, then connect again.")
      .arg(target.host)
      .arg(target.port);
}

}  // namespace

struct Session::Impl {
  explicit Impl(Session& s) : self(s) {}

  void open(const SessionTarget& target);
  void finishOpen(uint64_t generation, std::shared_ptr<Link> opened, const QString& error);
  void startWorkers(uint64_t generation);
  void close(const QString& reason, bool emit_always);
  void teardown(std::shared_ptr<Link> old);
  void applyPoll(uint64_t generation, const PollResult& poll);
  void onTick();
  void drainSamples();
  void refreshLive();
  void refreshKuka();
  void updateLoopRate(uint64_t count);
  void reportRsiChange(const xmate::rsi::SessionStatus& before, const xmate::rsi::SessionStatus& now);
  void startMotion(const QString& label, std::function<void(const MotionToken&)> job);
  bool controllerSilent();
  void startReconnect();
  void finishReconnect(uint64_t generation, bool ok);
  void restartWatchdog();
  void forgetSentSettings();

  Session& self;
  SessionTarget target;
  std::shared_ptr<Link> link;  // GUI thread only; the workers get raw pointers into it
  bool opening = false;
  bool reconnecting = false;   // a reconnect job is running: the client's session is being replaced
  uint64_t generation = 0;     // bumped by open/close: results of older links are ignored
  LiveState live;
  OperatorSettings settings;
  ProgramOverlay overlay;
  std::array<double, 16> model_tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::array<bool, 6> recorded_do{};
  uint64_t recorded_kuka_outputs = 0;
  const xmate::model::RobotSpec* spec = &xmate::model::robotSpec(xmate::XMATE7_PRO);
  QTimer timer;
  std::vector<xmate::client::StateSample> batch = std::vector<xmate::client::StateSample>(
      xmate::client::SampleRing::capacity());
  std::vector<xmate::arm::ArmSample> arm_batch = std::vector<xmate::arm::ArmSample>(
      std::max<size_t>(xmate::client::SampleRing::capacity(), 2048));
  QElapsedTimer clock;
  qint64 rate_start_ms = 0;
  uint64_t rate_start_count = 0;
  qint64 last_progress_ms = 0;
  uint64_t last_count = 0;
  BackgroundThreads background;
};

void Session::Impl::open(const SessionTarget& wanted) {
  close(QString(), false);
  try {
    spec = &wanted.spec();
  } catch (const std::exception& e) {
    emit self.openFailed(QString::fromStdString(e.what()));
    return;
  }
  target = wanted;
  opening = true;
  const uint64_t my_generation = ++generation;
  // Hand-off: the target is copied into the opener thread at its start.
  background.start([this, my_generation, wanted] {
    std::shared_ptr<Link> opened;
    QString error;
    try {
      opened = openLink(wanted);
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    // Hand-off: Qt queued invocation; the link moves to the GUI thread inside the shared_ptr.
    QMetaObject::invokeMethod(
        &self, [this, my_generation, opened, error] { finishOpen(my_generation, opened, error); },
        Qt::QueuedConnection);
  });
}

void Session::Impl::finishOpen(uint64_t my_generation, std::shared_ptr<Link> opened, const QString& error) {
  if (my_generation != generation) {  // closed or re-opened meanwhile
    if (opened) teardown(std::move(opened));
    return;
  }
  opening = false;
  if (!opened) {
    emit self.openFailed(error);
    return;
  }
  link = std::move(opened);
  forgetSentSettings();
  live = LiveState{};
  live.connected = true;
  live.simulated = link->server != nullptr;
  live.kuka_simulated = link->krc != nullptr;
  live.has_force_sensor = link->ft != nullptr;
  spec = &link->arm->spec();
  live.dof = spec->dof;
  live.capabilities = link->arm->capabilities();
  if (link->robot) model_tool = link->robot->toolFrame();
  recorded_do = {};
  recorded_kuka_outputs = 0;
  startWorkers(my_generation);
  clock.start();
  restartWatchdog();
  timer.start(kTickMs);
  emit self.opened();
}

void Session::Impl::startWorkers(uint64_t my_generation) {
  xmate::Robot* robot = link->robot.get();
  xmate::arm::Arm* arm = link->arm;
  link->commands = std::make_unique<JobWorker>("rci-commands", [this, robot, arm, my_generation] {
    PollResult poll = robot ? pollRobot(*robot) : pollArm(*arm);
    // Hand-off: Qt queued invocation of the poll result to the GUI thread.
    QMetaObject::invokeMethod(&self, [this, my_generation, poll] { applyPoll(my_generation, poll); },
                              Qt::QueuedConnection);
  });
  link->motions = std::make_unique<JobWorker>("rci-motion");
}

void Session::Impl::close(const QString& reason, bool emit_always) {
  const bool was_open = link != nullptr;
  ++generation;
  opening = false;
  reconnecting = false;
  timer.stop();
  if (link) {
    link->motion.stop.store(true);  // at once: the motion starts its ramp down while the teardown waits
    teardown(std::move(link));
    link.reset();
  }
  live = LiveState{};
  if (was_open || emit_always) emit self.closed(reason);
}

// Tears the link down on a background thread so a slow controller never blocks the window.
void Session::Impl::teardown(std::shared_ptr<Link> old) {
  // Hand-off: the link's ownership moves into the new thread (std::thread start synchronises).
  background.start([old = std::move(old)]() mutable {
    if (!shutdownLink(*old)) {
      // A worker did not end in time: its abandoned thread may still use the link, so keep it.
      std::fprintf(stderr, "rci-studio: a worker of the closed session did not end within %lld ms; it was "
                           "abandoned (the connection is closed)\n",
                   static_cast<long long>((kMotionStopWait + kWorkerEndWait).count()));
      new std::shared_ptr<Link>(std::move(old));  // deliberately leaked
    }
  });
}

void Session::Impl::applyPoll(uint64_t my_generation, const PollResult& poll) {
  if (my_generation != generation || !poll.ok) return;
  if (!link->robot) {
    live.inputs = poll.kuka_inputs;
    return;
  }
  live.motor_state = poll.motor_state;
  live.safety_stop = poll.safety_stop;
  live.digital_in = poll.digital_in;
  live.inputs = bitsOf(poll.digital_in);
  if (poll.tool != model_tool) {
    model_tool = poll.tool;
    link->model->SetCoor(model_tool);
  }
}

void Session::Impl::drainSamples() {
  if (link->rsi) {
    // Hand-off: the RSI link's SPSC sample ring; this (GUI) thread is its only consumer.
    const size_t n = link->rsi->takeSamples(arm_batch.data(), arm_batch.size());
    if (n > 0) emit self.armSamplesArrived(arm_batch.data(), int(n));
    return;
  }
  // Hand-off: the client's SPSC ring; this (GUI) thread is its only consumer.
  const size_t n = link->robot->connection().samples().popBatch(batch.data(), batch.size());
  if (n == 0) return;
  emit self.samplesArrived(batch.data(), int(n));
  for (size_t i = 0; i < n; ++i) arm_batch[i] = xmate::arm::armSample(batch[i]);
  emit self.armSamplesArrived(arm_batch.data(), int(n));
}

void Session::Impl::refreshKuka() {
  xmate::arm::RsiArm& arm = *link->rsi;
  live.has_arm_state = arm.latest(live.arm) || live.has_arm_state;
  const xmate::rsi::SessionStatus before = live.rsi;
  live.rsi = arm.sessionStatus();
  reportRsiChange(before, live.rsi);
  live.realtime = arm.link().realtimeStatus();
  updateLoopRate(live.arm.sample.cycle);
  if (link->krc) {
    live.krc = link->krc->krc().status();
    live.outputs = simulatedOutputs(arm, live.krc.digout);
  } else {
    live.outputs = recorded_kuka_outputs;
  }
  xmate::ft::Wrench reading;
  live.force_reading = link->ft && link->ft->latest(reading) && reading.status == 0 &&
                       xmate::net::monotonicNs() - reading.received_ns < 200'000'000;
  if (live.force_reading) live.force = reading.values;
}

// The event log hears when RSI starts, stops (and why) and starts again.
void Session::Impl::reportRsiChange(const xmate::rsi::SessionStatus& before, const xmate::rsi::SessionStatus& now) {
  using xmate::rsi::SessionPhase;
  if (now.phase == before.phase && now.session == before.session) return;
  const QString words = QString::fromStdString(xmate::rsi::describe(now));
  if (now.phase == SessionPhase::kStopped)
    emit self.eventReported(Session::EventLevel::kError, words, QString());
  else if (now.phase == SessionPhase::kRunning && (before.phase != SessionPhase::kRunning || now.session != before.session))
    emit self.eventReported(Session::EventLevel::kInfo, words, QString());
}

// Cycles per second over the last second, from a count that restarts with a new session (an xMate
// reconnected, a new RSI session).
void Session::Impl::updateLoopRate(uint64_t count) {
  const qint64 now = clock.elapsed();
  if (count < rate_start_count) rate_start_count = count;
  if (now - rate_start_ms >= 1000) {
    live.loop_rate_hz = double(count - rate_start_count) * 1000.0 / double(now - rate_start_ms);
    rate_start_ms = now;
    rate_start_count = count;
  }
}

void Session::Impl::refreshLive() {
  live.motion_running = link->motion.busy.load();
  live.stopping = false;
  if (link->rsi) {
    refreshKuka();
    return;
  }
  xmate::client::Connection& connection = link->robot->connection();
  if (connection.latestState(live.state)) {
    live.has_state = true;
    live.standstill = connection.standstill();
    live.stopping = xmate::client::stoppingOnItsOwn(live.standstill, live.state);
    live.tau_ext = externalJointTorques(*link->model, live.state.q, live.state.tau_ext_in_base);
    // The arm's view of the same state (not a second read: the two must agree).
    live.arm.sample = xmate::arm::armSample(xmate::client::makeStateSample(live.state, 0));
    live.arm.tcp = live.state.toolTobase_pos_m;
    live.has_arm_state = true;
  }
  live.realtime = connection.realtimeStatus();
  live.timing = connection.timing();
  updateLoopRate(live.timing.counters.states_received);
  if (link->server) {
    live.sim = link->server->status().sim;
    live.digital_out = live.sim.digital_out;
  } else {
    live.digital_out = recorded_do;
  }
  live.outputs = bitsOf(live.digital_out);
}

bool Session::Impl::controllerSilent() {
  const uint64_t count = live.timing.counters.states_received;
  const qint64 now = clock.elapsed();
  if (count != last_count) {
    last_count = count;
    last_progress_ms = now;
  }
  return now - last_progress_ms > kSilenceLimitMs;
}

// What the window sent to an earlier session (safety box, soft limits, collision thresholds) is
// not known to hold for this one: a rebooted or another controller starts with its own. The
// views, jog and pre-flight stop using it, and the event log says to send it again.
void Session::Impl::forgetSentSettings() {
  const bool had = settings.box.enabled || settings.soft_limits_enabled ||
                   std::any_of(settings.collision_thresholds.begin(), settings.collision_thresholds.end(),
                               [](double t) { return t != 0; });
  settings = OperatorSettings{};
  emit self.operatorSettingsChanged();
  if (had)
    emit self.eventReported(
        Session::EventLevel::kWarning,
        QStringLiteral("The safety box, soft limits and collision thresholds sent before are not shown or used any "
                       "more: the controller may have restarted with its own. Apply them again in their panels."),
        QString());
}

void Session::Impl::restartWatchdog() {
  rate_start_ms = last_progress_ms = clock.elapsed();
  rate_start_count = last_count = link->robot ? link->robot->connection().timing().counters.states_received : 0;
}

// The client's session is closed and re-opened on the command worker; meanwhile this thread does not
// touch the connection (its real-time status and counters are being replaced).
void Session::Impl::startReconnect() {
  reconnecting = true;
  emit self.reconnecting(QStringLiteral("No state from %1 for more than 1 s: reconnecting …").arg(target.describe()));
  Link* raw = link.get();
  const uint64_t my_generation = generation;
  // Hand-off: the command worker's job queue (JobWorker::post).
  link->commands->post([this, raw, my_generation] {
    const bool ok = reconnectLink(*raw);
    // Hand-off: Qt queued invocation of the outcome to the GUI thread.
    QMetaObject::invokeMethod(&self, [this, my_generation, ok] { finishReconnect(my_generation, ok); },
                              Qt::QueuedConnection);
  });
}

void Session::Impl::finishReconnect(uint64_t my_generation, bool ok) {
  if (my_generation != generation) return;
  reconnecting = false;
  if (!ok) {
    close(silenceReason(target), true);
    return;
  }
  restartWatchdog();
  forgetSentSettings();  // a controller that went silent has most likely rebooted
  emit self.reconnected();
}

void Session::Impl::onTick() {
  if (!link) return;
  link->motion.heartbeat_ns.store(steadyNs(), std::memory_order_relaxed);
  if (!reconnecting) {
    drainSamples();
    refreshLive();
    // An xMate that stopped sending is reconnected; a KUKA starts RSI again by itself (a new session).
    if (link->robot && controllerSilent()) startReconnect();
  }
  emit self.tick();
}

// ---- Session ----------------------------------------------------------------------------------

Session::Session(QObject* parent) : QObject(parent), impl_(std::make_unique<Impl>(*this)) {
  impl_->timer.setTimerType(Qt::PreciseTimer);
  connect(&impl_->timer, &QTimer::timeout, this, [this] { impl_->onTick(); });
}

Session::~Session() {
  impl_->close(QString(), false);
  impl_->background.joinAll();
}

void Session::open(const SessionTarget& target) { impl_->open(target); }
void Session::close() { impl_->close(QString(), false); }
bool Session::isOpen() const { return impl_->link != nullptr; }
bool Session::isOpening() const { return impl_->opening; }
bool Session::isReconnecting() const { return impl_->reconnecting; }
const SessionTarget& Session::target() const { return impl_->target; }
const LiveState& Session::live() const { return impl_->live; }
xmate::Robot* Session::robot() { return impl_->link ? impl_->link->robot.get() : nullptr; }
xmate::sim::Server* Session::simulator() { return impl_->link ? impl_->link->server.get() : nullptr; }
xmate::arm::Arm* Session::arm() { return impl_->link ? impl_->link->arm : nullptr; }
xmate::arm::RsiArm* Session::rsiArm() { return impl_->link ? impl_->link->rsi.get() : nullptr; }
xmate::sim::KrcServer* Session::kukaSimulator() { return impl_->link ? impl_->link->krc.get() : nullptr; }
const xmate::ft::NetFtClient* Session::forceSensor() { return impl_->link ? impl_->link->ft.get() : nullptr; }
const xmate::model::RobotSpec& Session::spec() const { return *impl_->spec; }
const OperatorSettings& Session::operatorSettings() const { return impl_->settings; }

void Session::setOperatorSettings(const OperatorSettings& settings) {
  impl_->settings = settings;
  emit operatorSettingsChanged();
}

const ProgramOverlay& Session::programOverlay() const { return impl_->overlay; }

void Session::setProgramOverlay(const ProgramOverlay& overlay) {
  impl_->overlay = overlay;
  emit programOverlayChanged();
}

void Session::recordDigitalOutput(int index, bool on) {
  if (impl_->link && impl_->link->rsi) {
    if (index >= 0 && index < 64) {
      const uint64_t bit = uint64_t{1} << index;
      impl_->recorded_kuka_outputs = on ? (impl_->recorded_kuka_outputs | bit) : (impl_->recorded_kuka_outputs & ~bit);
    }
    return;
  }
  if (index >= 0 && index < 6) impl_->recorded_do[size_t(index)] = on;
}

void Session::run(const QString& label, std::function<void(xmate::Robot&)> job) {
  if (impl_->link && !impl_->link->robot) {
    emit commandFinished(label, false, QStringLiteral("this works on an xMate only; %1 is connected").arg(impl_->target.describe()));
    return;
  }
  xmate::Robot* robot = impl_->link ? impl_->link->robot.get() : nullptr;
  runOnArm(label, [robot, job = std::move(job)](xmate::arm::Arm&) { job(*robot); });
}

void Session::runOnArm(const QString& label, ArmJob job) {
  if (!impl_->link) {
    emit commandFinished(label, false, kNotConnected);
    return;
  }
  xmate::arm::Arm* arm = impl_->link->arm;
  const uint64_t my_generation = impl_->generation;
  emit commandStarted(label);
  // Hand-off: the command worker's job queue (JobWorker::post, mutex + condition variable).
  impl_->link->commands->post([this, arm, my_generation, label, job = std::move(job)] {
    const auto [ok, message] = runCatching([&] { job(*arm); });
    // Hand-off: Qt queued invocation of the result to the GUI thread.
    QMetaObject::invokeMethod(
        this,
        [this, my_generation, label, ok, message] {
          if (my_generation == impl_->generation) emit commandFinished(label, ok, message);
        },
        Qt::QueuedConnection);
  });
}

void Session::runArmMotion(const QString& label, ArmMotionJob job) {
  xmate::arm::Arm* arm = impl_->link ? impl_->link->arm : nullptr;
  impl_->startMotion(label, [arm, job = std::move(job)](const MotionToken& token) { job(*arm, token); });
}

void Session::Impl::startMotion(const QString& label, std::function<void(const MotionToken&)> job) {
  Session* session = &self;
  if (!link) {
    emit self.commandFinished(label, false, kNotConnected);
    return;
  }
  MotionFlags& flags = link->motion;
  if (flags.busy.exchange(true)) {
    emit self.commandFinished(label, false, QStringLiteral("a motion is already running"));
    return;
  }
  flags.stop.store(false);
  flags.heartbeat_ns.store(steadyNs(), std::memory_order_relaxed);
  live.motion_running = true;
  const uint64_t my_generation = generation;
  emit self.motionStarted(label);
  // Hand-off: the result goes to the GUI thread by a Qt queued invocation; busy is cleared first.
  auto finish = [this, session, &flags, my_generation, label](bool ok, const QString& message) {
    flags.busy.store(false);
    QMetaObject::invokeMethod(
        session,
        [this, my_generation, label, ok, message] {
          if (my_generation != generation) return;
          live.motion_running = link && link->motion.busy.load();
          emit self.motionFinished(label, ok, message);
        },
        Qt::QueuedConnection);
  };
  // Hand-off: the motion worker's job queue (JobWorker::post). The link (and so `flags`) outlives
  // the job: shutdownLink joins the worker before it frees the link, or leaks the link.
  link->motions->post(
      [&flags, finish, job = std::move(job)] {
        const MotionToken token(flags.stop, flags.heartbeat_ns);
        const auto [ok, message] = runCatching([&] { job(token); });
        finish(ok, message);
      },
      [finish] { finish(false, QStringLiteral("not started: the connection closed first")); });
}

void Session::reportEvent(EventLevel level, const QString& text, const QString& detail) {
  emit eventReported(level, text, detail);
}

void Session::requestStop() {
  if (impl_->link && impl_->link->motion.busy.load()) impl_->link->motion.stop.store(true);
}

bool Session::stopRequested() const {
  return impl_->link && impl_->link->motion.busy.load() && impl_->link->motion.stop.load();
}

double MotionToken::windowSilenceMs() const {
  return double(steadyNs() - heartbeat_ns_->load(std::memory_order_relaxed)) * 1e-6;
}

}  // namespace rci::ui
