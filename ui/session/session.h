// SPDX-License-Identifier: Apache-2.0
// Session: the only door from the window to a robot (docs/architecture.md, "Threads and
// hand-offs"). For an xMate it owns the robot client (xmate::Robot) and, for the built-in simulator,
// the embedded sim::Server; for a KUKA the RSI arm (arm::RsiArm), the F/T sensor's client and, for
// the built-in KUKA simulator, the simulated KRC and sensor. Both families are reachable as one
// arm::Arm. Widgets never touch the network: they read live() on tick(), receive samples by
// samplesArrived() / armSamplesArrived(), and hand commands to run() / runOnArm() and motions to
// runArmMotion(), which execute on worker threads.
#pragma once

#include <QObject>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <xmate/rci_types.h>
#include <xmate/robot.h>
#include <xmate/types.h>

#include "arm/arm.h"
#include "client/connection.h"
#include "client/state_sample.h"
#include "model/robot_spec.h"
#include "net/realtime.h"
#include "rsi/session_monitor.h"
#include "sim/krc.h"
#include "sim/server.h"

namespace xmate::arm {
class RsiArm;
}
namespace xmate::ft {
class NetFtClient;
}
namespace xmate::sim {
class KrcServer;
}

namespace rci::ui {

// What to connect to.
struct SessionTarget {
  enum class Kind {
    kSimulator,      // the built-in xMate simulator
    kRobot,          // an xMate controller at host:port (RCI)
    kKukaSimulator,  // the built-in KUKA simulator: a simulated KRC running an RSI context, and an F/T sensor
    kKukaRobot,      // a KUKA robot controller sending RSI to this PC
  };
  Kind kind = Kind::kSimulator;
  xmate::XmateType type = xmate::XMATE7_PRO;       // xMate kinds
  QString host = QStringLiteral("192.168.0.160");  // kRobot only
  quint16 port = 1337;                              // kRobot only
  // kSimulator only: lock-step clock (deterministic tests) instead of real time.
  bool lockstep = false;
  // kSimulator only: DO k drives DI k.
  bool loopback = false;
  // KUKA kinds: the model's file stem ("kr6_r900_sixx", "kr16_2").
  QString kuka_model = QStringLiteral("kr6_r900_sixx");
  // kKukaRobot: the RSI Ethernet config file (this PC's listen address and port come from it).
  QString rsi_config;
  // KUKA kinds: the RSI context the robot runs. "": the built-in simulator runs the sample that
  // ships (resources/rsi/rci_replay.rsi.xml); for a robot, the one beside rsi_config naming it.
  QString rsi_context;
  // kKukaRobot: the F/T sensor's address "HOST" or "HOST:PORT" ("" = no sensor: no hand guiding).
  QString ft_sensor;

  bool isKuka() const { return kind == Kind::kKukaSimulator || kind == Kind::kKukaRobot; }
  bool isSimulator() const { return kind == Kind::kSimulator || kind == Kind::kKukaSimulator; }
  // The model; throws std::invalid_argument for an unknown kuka_model.
  const xmate::model::RobotSpec& spec() const;
  // "Simulator (xMate7 Pro)" / "Robot 192.168.0.160:1337 (xMate7 Pro)" / "KUKA simulator (KR 6 R900
  // sixx)" / "KUKA RSI on 192.168.1.2:49152 (KR 6 R900 sixx)"
  QString describe() const;
};

// Everything the panels and the status bar show, refreshed on the GUI thread before each tick().
struct LiveState {
  bool connected = false;
  bool has_state = false;              // at least one RobotState arrived
  RCI::robot::RobotState state;        // the newest state
  std::array<double, 7> tau_ext{};     // external joint torques, Nm (J^T of tau_ext_in_base)
  int dof = 7;                         // 6 for xMate3 / xMate7 (6-axis models)
  int motor_state = 0;                 // 1 on, 0 off (polled by the command worker, ~5 Hz)
  int safety_stop = 1;                 // 1 none, 2 ESTOP, 3 GSTOP (polled, ~5 Hz)
  std::array<bool, 6> digital_in{};    // polled, ~5 Hz
  std::array<bool, 6> digital_out{};   // as last set through run() (the robot cannot report it)
  bool motion_running = false;         // a runArmMotion() job is queued or executing
  // The arm is coming to rest on its own after a stop, a recovered error or the end of hand guiding
  // (xmate::client::stoppingOnItsOwn): motions wait, the window says "stopping ...". xMate only.
  bool stopping = false;
  xmate::client::Standstill standstill;  // the fastest joint and whether the arm stands still
  xmate::net::RealtimeStatus realtime; // what the client's real-time thread got
  xmate::client::SessionTiming timing; // loop rate, jitter, counters
  double loop_rate_hz = 0;             // states per second over the last second
  bool simulated = false;
  xmate::sim::SimStatus sim;           // valid when simulated (xMate)

  // Both families, for family-neutral views (3D, plots, program): what the arm offers, its newest
  // state in SI units.
  xmate::arm::Capabilities capabilities = 0;
  bool has_arm_state = false;
  xmate::arm::ArmState arm;
  // Digital IO of either family: bit k is the k-th signal of Session::arm()->inputNames() /
  // outputNames() (inputs polled ~5 Hz; outputs as set through this window, a simulator's own).
  uint64_t inputs = 0;
  uint64_t outputs = 0;
  // A KUKA over RSI:
  xmate::rsi::SessionStatus rsi;       // waiting / running / stopped and why; cycle, Delay, answer p99
  bool kuka_simulated = false;
  xmate::sim::KrcStatus krc;           // valid when kuka_simulated
  bool has_force_sensor = false;       // an F/T sensor is configured
  bool force_reading = false;          // ... and its newest reading is recent and healthy
  std::array<double, 6> force{};       // the sensor's reading: Fx Fy Fz (N), Tx Ty Tz (Nm), sensor frame
};

// Settings the window sent that a robot cannot report back. The panel that sends one records it
// here after the command succeeded (setOperatorSettings); views (3D box, collision bars) read it.
struct SafetyBox {
  bool enabled = false;
  std::array<double, 3> size{1.2, 1.2, 1.2};                     // m, along the box frame's axes
  std::array<double, 16> frame{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.5, 0, 0, 0, 1};  // centre, base frame
};
struct OperatorSettings {
  SafetyBox box;
  std::array<double, 7> collision_thresholds{};  // Nm per joint; 0 = not set by this window
  bool soft_limits_enabled = false;
  std::array<double, 7> soft_upper_deg{}, soft_lower_deg{};
};

// What the Program panel shows in the 3D view: the taught waypoints (TCP positions in the
// base frame, m, with their names) and the planned TCP path through them.
struct ProgramOverlay {
  std::vector<std::array<double, 3>> waypoints;
  std::vector<QString> labels;               // one per waypoint ("P1", ...)
  std::vector<std::array<double, 3>> path;   // polyline, m
  int selected = -1;                         // index into waypoints, -1 if none
};

// What a motion job (Session::runArmMotion) gets besides the arm: its stop token, set by
// requestStop() and by close / disconnect / quit, and the age of the window's heartbeat (the display
// tick), so that a motion the operator holds on (jog) ends when the window stops responding.
// Valid while the job runs; every call is lock-free and real-time safe (any thread).
class MotionToken {
 public:
  MotionToken(const std::atomic<bool>& stop, const std::atomic<int64_t>& heartbeat_ns)
      : stop_(&stop), heartbeat_ns_(&heartbeat_ns) {}
  bool stopRequested() const { return stop_->load(std::memory_order_relaxed); }
  // The flag itself, for xmate::teach::ExecutorOptions::stop_token.
  const std::atomic<bool>& stopFlag() const { return *stop_; }
  // Milliseconds since the GUI thread last ran its display tick (~33 ms when the window is healthy).
  double windowSilenceMs() const;

 private:
  const std::atomic<bool>* stop_;
  const std::atomic<int64_t>* heartbeat_ns_;
};

class Session : public QObject {
  Q_OBJECT
 public:
  // How much an event reported for the log (reportEvent) matters.
  enum class EventLevel { kInfo, kWarning, kError };
  Q_ENUM(EventLevel)

  explicit Session(QObject* parent = nullptr);
  ~Session() override;  // close()s

  // Connects in the background; emits opened() or openFailed(reason). Closes any open session first.
  void open(const SessionTarget& target);
  // Stops motion, disconnects, stops the embedded simulator. Emits closed("").
  void close();
  bool isOpen() const;
  // True between open() and opened()/openFailed().
  bool isOpening() const;
  // True while the session tries to re-open after the controller stopped sending states
  // for more than 1 s (e.g. after rebootRobot()); between reconnecting() and reconnected()/closed().
  bool isReconnecting() const;
  const SessionTarget& target() const;
  // The model of the open session, or of the target last opened (xMate7 Pro before any). GUI thread.
  const xmate::model::RobotSpec& spec() const;

  // GUI thread only. Valid between opened() and closed().
  const LiveState& live() const;
  // The client (for type(), toolFrame(), load()); nullptr when closed. Do not call commands on it
  // from the GUI thread: use run().
  xmate::Robot* robot();
  // The embedded simulator (scene: external wrench, e-stop, DI levels); nullptr on a real robot.
  // Its calls are quick and may be made from the GUI thread.
  xmate::sim::Server* simulator();
  // The open arm of either family (for spec(), capabilities(), IO names); nullptr when
  // closed. Commands and motions on it go through runOnArm() / runArmMotion().
  xmate::arm::Arm* arm();
  // A KUKA's RSI arm (its context, limits and joint stream state); nullptr otherwise.
  xmate::arm::RsiArm* rsiArm();
  // The built-in KUKA simulator (the operator's push, faults); nullptr otherwise. Its scene and
  // fault calls are real-time safe and may be made from the GUI thread.
  xmate::sim::KrcServer* kukaSimulator();
  // A KUKA's F/T sensor client (latest() from any thread); nullptr without a sensor.
  const xmate::ft::NetFtClient* forceSensor();

  // Queues job on the command worker (one at a time, in order). When it returns, emits
  // commandFinished(label, true, ""), or (label, false, what()) if it threw. Never blocks.
  void run(const QString& label, std::function<void(xmate::Robot&)> job);
  // A command on the arm (IO) on the command worker, as run() does for the xMate client.
  using ArmJob = std::function<void(xmate::arm::Arm&)>;
  void runOnArm(const QString& label, ArmJob job);
  // Runs a motion on the arm (its runJointMotion / runCartesianMotion, or the teach executor) on the
  // motion worker; at most one at a time (refused with commandFinished(label, false, "a motion is
  // already running") otherwise). The job must poll its token's stopRequested() -- in its real-time
  // callback and in any wait -- and finish smoothly when it is set: requestStop(), close(), a lost
  // connection and the window's end all set it. When the job has not ended 1.5 s after close(), the
  // session stops the motion on the controller and closes the connection under it
  // (docs/reliability.md, "Stop and disconnect"). motionFinished(label, ...) follows, unless the
  // session closed meanwhile. GUI thread.
  using ArmMotionJob = std::function<void(xmate::arm::Arm&, const MotionToken&)>;
  void runArmMotion(const QString& label, ArmMotionJob job);
  // The window's record of settings sent (see OperatorSettings). GUI thread only.
  const OperatorSettings& operatorSettings() const;
  // The program overlay of the 3D view. GUI thread only.
  const ProgramOverlay& programOverlay() const;
  void setProgramOverlay(const ProgramOverlay& overlay);  // emits programOverlayChanged()
  void setOperatorSettings(const OperatorSettings& settings);  // emits operatorSettingsChanged()

  // A panel that set DO index (0..5; a KUKA's: the index into arm()->outputNames(), < 64)
  // records it here, so live().digital_out / outputs show it on a real robot (the simulators
  // report their outputs themselves). GUI thread only.
  void recordDigitalOutput(int index, bool on);

  // A panel tells the event log what happened in operator words (e.g. the outcome of a
  // program run); emits eventReported(). detail: the programmer's words, for a tooltip. GUI thread.
  void reportEvent(EventLevel level, const QString& text, const QString& detail = QString());

  // Asks the running motion to stop (its token); at once, on the calling thread. GUI thread.
  void requestStop();
  bool stopRequested() const;         // the running motion's token is set. GUI thread.

 signals:
  void opened();
  void openFailed(const QString& reason);
  void closed(const QString& reason);  // "" when asked for; else why (controller gone, ...)
  // The controller went silent and the session is re-opening it / succeeded. If it
  // cannot (10 s simulator, 60 s robot), closed(reason) follows.
  void reconnecting(const QString& reason);
  void reconnected();
  // Display rate (30 Hz): live() was refreshed.
  void tick();
  // Display rate, before tick(): the samples the real-time thread recorded since the last batch,
  // oldest first. The pointer is valid only during the call (connect directly, GUI thread).
  void samplesArrived(const xmate::client::StateSample* samples, int count);
  // The same cycles as arm samples, for either family (after samplesArrived on an xMate).
  void armSamplesArrived(const xmate::arm::ArmSample* samples, int count);
  // Run() queued the job labelled label (commandFinished follows).
  void commandStarted(const QString& label);
  void commandFinished(const QString& label, bool ok, const QString& message);
  void operatorSettingsChanged();
  void programOverlayChanged();
  void motionStarted(const QString& label);
  void motionFinished(const QString& label, bool ok, const QString& message);
  // See reportEvent().
  void eventReported(rci::ui::Session::EventLevel level, const QString& text, const QString& detail);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// "xMate7 Pro" etc.
QString modelName(xmate::XmateType type);
// Parses "xmate7_pro" | "xmate3_pro" | "xmate7" | "xmate3"; false if unknown.
bool parseModel(const QString& text, xmate::XmateType& type);

}  // namespace rci::ui
