// SPDX-License-Identifier: Apache-2.0
// The executor: runs a program on the calling thread through one robot port (robot_port.h; one
// per robot family) after a pre-flight that must find no problem -- MOVEJ / MOVEL / MOVEC with the
// jerk-limited planners, PATH re-timed within the joint limits (path_timing.h) after a joint move to
// its start, WAIT, SET_DO, WAIT_DI. Another thread may pause, resume, stop, single-step and change
// the speed override at any time, and read the progress without locks. docs/teach.md describes
// the behaviour.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <xmate/robot.h>

#include "model/arm_kinematics.h"
#include "teach/preflight.h"
#include "teach/program.h"
#include "teach/robot_port.h"
#include "teach/time_scaling.h"

namespace xmate::arm {
class Arm;
}

namespace xmate::teach {

// progress() reads these without locks from any thread.
static_assert(std::atomic<double>::is_always_lock_free && std::atomic<long>::is_always_lock_free);

enum class RunState : int {
  kIdle,      // not started
  kChecking,  // pre-flight
  kRunning,
  kPausing,   // ramping down to a stop on the path
  kPaused,    // holding (on the path, or between instructions)
  kStopping,  // ramping down, then the program ends
  kFinished,  // every instruction done
  kStopped,   // ended by stop()
  kRefused,   // the pre-flight found problems; nothing moved
  kFailed,    // an instruction failed (controller error, DI timeout, planning)
};
const char* runStateName(RunState state);

enum class InstructionStatus { kNotRun, kRunning, kDone, kStopped, kFailed };
const char* statusName(InstructionStatus status);

struct InstructionReport {
  InstructionStatus status = InstructionStatus::kNotRun;
  std::string message;              // why it failed or was stopped ("" when done)
  std::array<double, 7> q{};        // reached joints (rad), measured after the instruction
  std::array<double, 16> pose{};    // reached TCP pose, row-major (m)
  double psi = 0;                   // reached arm angle (rad)
  double duration = 0;              // s: controller cycles for motions, wall time otherwise
  double max_joint_error = 0;       // motions: max over the motion of max_j |q_c - q| (rad)
  double max_tcp_error = 0;         // motions: max |TCP commanded - measured| position (m)
  // Motions: controller time from the last command until the arm was at rest (s). If it was not at
  // rest within 1 s, settled is false and settle_error the largest |q_c - q| then (rad).
  double settle_time = 0;
  bool settled = true;
  double settle_error = 0;
  // PATH only (docs/teach.md, "Replaying a path"). duration above is the replay of the path alone;
  // the joint move to its first sample before it took lead_in seconds (0: the arm was there).
  double lead_in = 0;                 // s, controller cycles
  double nominal_duration = 0;        // s: the path's duration / speed, as if never slowed
  double path_joint_deviation = 0;    // rad: the largest joint deviation of the measured joints from the path
  double path_tcp_deviation = 0;      // m: the largest TCP deviation from the path
  double slowest_pace = 1;            // the lowest pace relative to the asked one (1: never slowed)
  double slowed_share = 0;            // share of the path's time replayed slower than asked
  double slowest_at = 0;              // s of the path where the pace is lowest
};

struct RunReport {
  RunState outcome = RunState::kIdle;
  std::string message;               // the failure or refusal, naming the instruction
  long failed_instruction = -1;      // 0-based index of the failing instruction, -1 if none
  std::vector<Problem> problems;     // the pre-flight's (outcome kRefused)
  std::vector<Problem> notices;      // what the pre-flight announces (a PATH's lead-in move)
  std::vector<InstructionReport> instructions;
  double duration = 0;               // s, wall time of the run
};

struct ExecutorOptions {
  double speed_override = 1.0;  // 0.1 .. 1.0 (also settable while running)
  bool single_step = false;     // pause after each instruction
  bool has_soft_limits = false; // for the pre-flight (the robot's setJointLimit), rad
  std::array<double, 7> soft_lower{}, soft_upper{};
  bool has_box = false;         // for the pre-flight (the robot's setCartesianLimit)
  SafetyBox box;
  // An outside stop request, polled with stop() in pauses, WAIT, WAIT_DI and every motion cycle:
  // once it is set the run stops smoothly as by stop(). E.g. the window's session token, set on
  // Stop, disconnect and quit. Must outlive run(); nullptr for none.
  const std::atomic<bool>* stop_token = nullptr;
  // Called on the run's thread (never the real-time one) once the pre-flight passed, before
  // anything moves, with what it announces (RunReport::notices; possibly none).
  std::function<void(const std::vector<Problem>& notices)> on_notices;
  // Called on the run's thread (never the real-time one) when an instruction starts and ends.
  std::function<void(size_t index)> on_start;
  std::function<void(size_t index, const InstructionReport& report)> on_done;
};

// A lock-free snapshot of the run.
struct Progress {
  RunState state = RunState::kIdle;
  long instruction = -1;    // 0-based index of the current instruction, -1 before the first
  double fraction = 0;      // of the current instruction, 0..1 (plan time / duration for motions)
  double speed_override = 1.0;
};

// One executor can run many programs, one at a time, on any robot, through one port
// (robot_port.h) that the robot's family implements. The GUI keeps one for its Program panel
// (controls and progress work at any time) and calls run() from its motion worker
// (Session::runArmMotion), which hands it the arm.
class Executor : private MotionControl {
 public:
  Executor() = default;
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  // Runs the program through `port` to its end (blocking, on the calling thread). Throws nothing
  // for run-time failures (they are in the report); std::logic_error when another run() is active.
  // The options' soft limits and box apply to the pre-flight.
  RunReport run(RobotPort& port, const Program& program, const ExecutorOptions& options = {});
  // The same on an arm of either family, through its port (arm_port.h). On a KUKA over RSI the
  // link must be running; SET_DO and WAIT_DI reach the signals its context wires to the PC (none
  // wired: the program fails at the first of them, saying so).
  RunReport run(arm::Arm& arm, const Program& program, const ExecutorOptions& options = {});
  // The same on a robot of the vendor API (an xMate), through its port (rci_port.h).
  RunReport run(Robot& robot, const Program& program, const ExecutorOptions& options = {});

  // ---- Thread-safe controls (any thread, any time; no effect when not running) ----------------
  void pause();                       // smooth stop on the path; holds until resume()/stop()
  void resume();                      // ramps back up; in single-step mode runs one more instruction
  void stop();                        // smooth stop, then the run ends (outcome kStopped)
  void setSingleStep(bool on);
  void setSpeedOverride(double ratio);  // clamped to [0.1, 1.0]; ramps smoothly
  Progress progress() const;

 private:
  RobotPort* port_ = nullptr;             // during run()
  const std::atomic<bool>* stop_token_ = nullptr;  // during run(): ExecutorOptions::stop_token
  bool has_soft_limits_ = false;  // during run(): the options' soft limits, for IK of pose targets
  std::array<double, 7> soft_lower_{}, soft_upper_{};
  std::atomic<bool> active_{false};
  std::atomic<bool> pause_requested_{false};
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> single_step_{false};
  std::atomic<double> override_{1.0};
  std::atomic<int> state_{int(RunState::kIdle)};
  std::atomic<long> instruction_{-1};
  std::atomic<double> fraction_{0};
  // The part of the instruction's progress a motion fills (0..1 by default): a PATH's lead-in and
  // its path share one progress. Set on the run's thread before a motion starts.
  double fraction_from_ = 0, fraction_span_ = 1;

  void setState(RunState s) { state_.store(int(s)); }
  // stop() was called or the options' stop token is set. Real-time safe.
  bool stopping() const {
    return stop_requested_.load(std::memory_order_relaxed) ||
           (stop_token_ && stop_token_->load(std::memory_order_relaxed));
  }

  // ---- MotionControl: the port's motion asks these on the real-time thread each cycle ----------
  double speedOverride() const override { return override_.load(std::memory_order_relaxed); }
  // What the time scaling's k should go to (0 to pause or stop, else the override), setting the
  // state to show.
  double scalingTarget(const TimeScaling& scaling) override {
    const bool stop_now = stopping();
    const bool pausing = pause_requested_.load(std::memory_order_relaxed);
    if (stop_now) setState(RunState::kStopping);
    else if (pausing) setState(scaling.value() == 0 ? RunState::kPaused : RunState::kPausing);
    else setState(RunState::kRunning);
    return stop_now || pausing ? 0.0 : override_.load(std::memory_order_relaxed);
  }
  // Stop requested and the ramp has reached zero: the motion ends where it stands.
  bool stoppedHere(const TimeScaling& scaling) const override {
    return stopping() && scaling.value() == 0 && scaling.settled();
  }
  // A motion's progress (0..1) as the instruction's.
  void storeFraction(double f) override {
    fraction_.store(fraction_from_ + fraction_span_ * f, std::memory_order_relaxed);
  }

  // Blocks while paused (between instructions); false when stop() ended the wait.
  bool waitWhilePaused();
  RunReport runProgram(const Program& program, const ExecutorOptions& options);
  InstructionReport execute(const Program& program, size_t index);
  // The model motions plan with: the program's tool (else the robot's), the soft limits.
  model::ArmKinematics motionModel(const Program& program) const;
  // MOVEJ, MOVEL, MOVEC (also a PATH's lead-in, which is a MOVEJ built for it), through the port.
  void runMotion(const Program& program, const Instruction& in, InstructionReport& report);
  // PATH (executor_path.cpp): re-timed, checked, the lead-in joint move to its first sample, then
  // the timing streamed through the port and the measured joints compared with the path.
  void runPath(const Program& program, size_t index, InstructionReport& report);
  // The lead-in joint move to a PATH's first sample; false when it was stopped (the report says so).
  bool leadIn(const Program& program, const Instruction& in, InstructionReport& report);
  void runWait(const Instruction& in, InstructionReport& report);
  void runWaitDi(const Program& program, size_t index, InstructionReport& report);
  void recordReached(InstructionReport& report);
};

}  // namespace xmate::teach
