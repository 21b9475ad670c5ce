// SPDX-License-Identifier: Apache-2.0
// The executor's run loop and controls (executor.h): pre-flight, then one instruction after the
// other with pauses between them, WAIT / SET_DO / WAIT_DI, failures turned into the report.
// Motions go through the robot's port (robot_port.h), PATH is prepared in executor_path.cpp.
#include "teach/executor.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>
#include <numbers>
#include <thread>

#include <xmate/exception.h>

#include "teach/arm_port.h"
#include "teach/program_io.h"
#include "teach/rci_port.h"

namespace xmate::teach {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Clears `flag` when run() returns (run() is not re-entrant).
struct ActiveGuard {
  std::atomic<bool>& flag;
  ~ActiveGuard() { flag.store(false); }
};

}  // namespace

const char* runStateName(RunState state) {
  switch (state) {
    case RunState::kIdle: return "idle";
    case RunState::kChecking: return "checking";
    case RunState::kRunning: return "running";
    case RunState::kPausing: return "pausing";
    case RunState::kPaused: return "paused";
    case RunState::kStopping: return "stopping";
    case RunState::kFinished: return "finished";
    case RunState::kStopped: return "stopped";
    case RunState::kRefused: return "refused";
    case RunState::kFailed: return "failed";
  }
  return "?";
}

const char* statusName(InstructionStatus status) {
  switch (status) {
    case InstructionStatus::kNotRun: return "not run";
    case InstructionStatus::kRunning: return "running";
    case InstructionStatus::kDone: return "done";
    case InstructionStatus::kStopped: return "stopped";
    case InstructionStatus::kFailed: return "failed";
  }
  return "?";
}

void Executor::pause() { pause_requested_.store(true); }
void Executor::resume() { pause_requested_.store(false); }
void Executor::stop() { stop_requested_.store(true); }
void Executor::setSingleStep(bool on) { single_step_.store(on); }
void Executor::setSpeedOverride(double ratio) {
  override_.store(ratio >= 0.1 ? (ratio <= 1.0 ? ratio : 1.0) : 0.1);  // NaN -> 0.1
}

Progress Executor::progress() const {
  Progress p;
  p.state = RunState(state_.load());
  p.instruction = instruction_.load();
  p.fraction = fraction_.load();
  p.speed_override = override_.load();
  return p;
}

bool Executor::waitWhilePaused() {
  if (!pause_requested_.load()) return !stopping();
  setState(RunState::kPaused);
  while (pause_requested_.load() && !stopping()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  if (stopping()) return false;
  setState(RunState::kRunning);
  return true;
}

RunReport Executor::run(Robot& robot, const Program& program, const ExecutorOptions& options) {
  RciPort port(robot);
  return run(port, program, options);
}

RunReport Executor::run(arm::Arm& arm, const Program& program, const ExecutorOptions& options) {
  const std::unique_ptr<RobotPort> port = armPort(arm, program);
  return run(*port, program, options);
}

RunReport Executor::run(RobotPort& port, const Program& program, const ExecutorOptions& options) {
  if (active_.exchange(true)) throw std::logic_error("Executor::run: a program is already running on this executor");
  ActiveGuard guard{active_};
  port_ = &port;
  return runProgram(program, options);
}

RunReport Executor::runProgram(const Program& program, const ExecutorOptions& options) {
  stop_token_ = options.stop_token;
  has_soft_limits_ = options.has_soft_limits;
  soft_lower_ = options.soft_lower;
  soft_upper_ = options.soft_upper;
  pause_requested_.store(false);
  stop_requested_.store(false);
  single_step_.store(options.single_step);
  setSpeedOverride(options.speed_override);
  instruction_.store(-1);
  fraction_.store(0);
  const auto start = Clock::now();

  RunReport report;
  report.instructions.resize(program.instructions.size());
  setState(RunState::kChecking);
  try {
    requireRobot(program, port_->spec());
    TraceOptions trace;
    const RobotPort::Reading state = port_->read();
    trace.q_start = state.q;
    trace.tool = port_->toolFrame();
    trace.has_tcp = true;
    trace.tcp = state.tcp;
    trace.has_soft_limits = options.has_soft_limits;
    trace.soft_lower = options.soft_lower;
    trace.soft_upper = options.soft_upper;
    trace.has_box = options.has_box;
    trace.box = options.box;
    trace.has_joint_bounds = port_->reachableBounds(trace.joint_lower, trace.joint_upper);
    ProgramTrace checked = traceProgram(program, trace);
    report.problems = std::move(checked.problems);
    report.notices = std::move(checked.notices);
  } catch (const std::exception& e) {
    report.problems.push_back({0, e.what()});
  }
  if (!report.problems.empty()) {
    report.outcome = RunState::kRefused;
    report.message = "pre-flight found " + std::to_string(report.problems.size()) + " problem(s); nothing moved:\n" +
                     problemsText(report.problems);
    setState(report.outcome);
    return report;
  }

  if (options.on_notices) options.on_notices(report.notices);
  setState(RunState::kRunning);
  report.outcome = RunState::kFinished;
  for (size_t i = 0; i < program.instructions.size(); ++i) {
    if (!waitWhilePaused()) {
      report.outcome = RunState::kStopped;
      break;
    }
    instruction_.store(long(i));
    fraction_.store(0);
    if (options.on_start) options.on_start(i);
    InstructionReport& r = report.instructions[i];
    r = execute(program, i);
    fraction_.store(1);
    if (options.on_done) options.on_done(i, r);
    if (r.status == InstructionStatus::kFailed) {
      report.outcome = RunState::kFailed;
      report.failed_instruction = long(i);
      report.message = r.message;
      break;
    }
    if (r.status == InstructionStatus::kStopped || stopping()) {
      report.outcome = RunState::kStopped;
      report.message = describe(program, i) + ": stopped by the operator";
      break;
    }
    if (single_step_.load() && i + 1 < program.instructions.size()) pause_requested_.store(true);
  }
  report.duration = secondsSince(start);
  setState(report.outcome);
  return report;
}

InstructionReport Executor::execute(const Program& program, size_t index) {
  const Instruction& in = program.instructions[index];
  InstructionReport r;
  r.status = InstructionStatus::kRunning;
  const auto start = Clock::now();
  try {
    switch (in.type) {
      case InstructionType::kMoveJ:
      case InstructionType::kMoveL:
      case InstructionType::kMoveC:
        runMotion(program, in, r);
        break;
      case InstructionType::kPath:
        runPath(program, index, r);
        break;
      case InstructionType::kWait:
        runWait(in, r);
        r.duration = secondsSince(start);
        break;
      case InstructionType::kSetDo:
        port_->setDO(in.signal, in.value);
        r.duration = secondsSince(start);
        break;
      case InstructionType::kWaitDi:
        runWaitDi(program, index, r);
        r.duration = secondsSince(start);
        break;
    }
    if (r.status == InstructionStatus::kRunning) r.status = InstructionStatus::kDone;
  } catch (const ControlException& e) {
    r.status = InstructionStatus::kFailed;
    r.message = describe(program, index) + ": the controller aborted the motion: " + e.what();
  } catch (const std::exception& e) {
    r.status = InstructionStatus::kFailed;
    r.message = describe(program, index) + ": " + e.what();
  }
  try {
    recordReached(r);
  } catch (const std::exception&) {
    // The robot may be unreachable after a failure; the reached pose then stays zero.
  }
  return r;
}

model::ArmKinematics Executor::motionModel(const Program& program) const {
  model::ArmKinematics model(port_->spec());
  model.SetCoor(program.has_tool ? program.tool : port_->toolFrame());  // the TCP its poses are poses of
  model.SetSpeedCheckInterval(0);
  if (has_soft_limits_) {
    std::array<double, 7> upper{}, lower{};
    for (int i = 0; i < 7; ++i) {
      upper[i] = soft_upper_[i] * 180.0 / std::numbers::pi;
      lower[i] = soft_lower_[i] * 180.0 / std::numbers::pi;
    }
    model.SetJointLimit(upper, lower);  // IK of pose targets as the pre-flight resolved them
  }
  return model;
}

void Executor::runMotion(const Program& program, const Instruction& in, InstructionReport& report) {
  port_->move(program, in, motionModel(program), *this, report);
}

void Executor::runWait(const Instruction& in, InstructionReport& r) {
  // Counts only time not paused; stop() ends it early.
  double waited = 0;
  auto last = Clock::now();
  while (waited * 1000 < in.ms) {
    if (stopping()) {
      r.status = InstructionStatus::kStopped;
      r.message = "stopped by the operator";
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const auto now = Clock::now();
    if (!pause_requested_.load()) waited += std::chrono::duration<double>(now - last).count();
    setState(pause_requested_.load() ? RunState::kPaused : RunState::kRunning);
    last = now;
    fraction_.store(in.ms > 0 ? std::min(1.0, waited * 1000 / in.ms) : 1.0);
  }
}

void Executor::runWaitDi(const Program& program, size_t index, InstructionReport& r) {
  const Instruction& in = program.instructions[index];
  const auto start = Clock::now();
  for (;;) {
    if (port_->getDI(in.signal) == in.value) return;
    if (stopping()) {
      r.status = InstructionStatus::kStopped;
      r.message = "stopped by the operator";
      return;
    }
    const double waited = secondsSince(start) * 1000;
    fraction_.store(std::min(1.0, waited / in.timeout_ms));
    if (waited >= in.timeout_ms) {
      r.status = InstructionStatus::kFailed;
      r.message = describe(program, index) + ": " + diName(program.robot->family, in.signal) + " did not become " +
                  (in.value ? "true" : "false") + " within " + std::to_string(in.timeout_ms) +
                  " ms; check the sensor and its wiring, or raise timeout_ms";
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

void Executor::recordReached(InstructionReport& r) {
  const RobotPort::Reading s = port_->read();
  r.q = s.q;
  r.pose = s.tcp;
  r.psi = s.psi;
}

}  // namespace xmate::teach
