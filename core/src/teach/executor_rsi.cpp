// SPDX-License-Identifier: Apache-2.0
// The executor on a KUKA over RSI (executor.h): every motion becomes joints every 1 ms of plan time
// -- MOVEJ from planning::JointLine, MOVEL/MOVEC through IK of the timed Cartesian path, a PATH
// from its re-timing (executor_path.cpp) -- checked at the RSI cycle against the axis ranges,
// speeds and the context's AXISCORR limits before it starts, then streamed one command per RSI
// cycle by rsi::JointStream. The plan time advances by k * cycle as on the xMate, so pause, stop and
// the override act the same way. The per-cycle code runs on the link's real-time thread: atomics,
// locals and the precomputed joints only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include <xmate/exception.h>

#include "client/move_check.h"
#include "planning/joint_line.h"
#include "arm/rci_arm.h"
#include "arm/rsi_arm.h"
#include "rsi/digital_io.h"
#include "rsi/joint_stream.h"
#include "teach/executor.h"
#include "teach/executor_path.h"
#include "teach/path_timing.h"
#include "teach/plan_scaling.h"
#include "teach/settle.h"
#include "teach/robot_port.h"
#include "teach/targets.h"

namespace xmate::teach {
namespace {

constexpr double kGridDt = 1e-3;  // plan time between two precomputed joint samples

// A KUKA through its RSI stream. Its TCP is the model's at the commanded joints with the program's
// tool (RSI does not tell the PC which tool the controller has active); its digital IO is what the
// context wires to the PC (rsi::DigitalIo).
class RsiPort : public RobotPort {
 public:
  RsiPort(rsi::JointStream& stream, rsi::DigitalIo* io, const std::array<double, 16>& tool)
      : stream_(stream), io_(io), model_(stream.spec()) {
    model_.SetCoor(tool);
    tool_ = tool;
  }
  const model::RobotSpec& spec() const override { return stream_.spec(); }
  Reading read() override {
    rsi::StreamState s;
    if (!stream_.state(s))
      throw std::runtime_error("RSI is not running: no <Rob> datagram has arrived; start the KRL program (RSI_ON, "
                               "RSI_MOVECORR) on the robot");
    Reading r;
    for (size_t i = 0; i < 6; ++i) r.q[i] = s.q[i];
    r.tcp = model_.GetCartPose(r.q);
    return r;
  }
  std::array<double, 16> toolFrame() override { return tool_; }
  void setDO(int signal, bool value) override { io().setOutput(signal, value); }
  bool getDI(int signal) override { return io().input(signal); }
  bool reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) override {
    return stream_.reachableBounds(lower, upper);
  }

 private:
  rsi::DigitalIo& io() {
    if (!io_)
      throw std::runtime_error("the RSI context wires no digital inputs or outputs to the PC: wire DIGIN / DIGOUT "
                               "objects to the ETHERNET object (as resources/rsi/rci_replay.rsi.xml does), or "
                               "remove SET_DO and WAIT_DI from the program");
    return *io_;
  }
  rsi::JointStream& stream_;
  rsi::DigitalIo* io_;
  model::ArmKinematics model_;
  std::array<double, 16> tool_{};
};

// The stream's newest state; MotionException when RSI is not running (no <Rob> yet).
rsi::StreamState runningState(const rsi::JointStream& stream) {
  rsi::StreamState state;
  if (!stream.state(state)) throw MotionException("RSI is not running: start the KRL program on the robot");
  return state;
}

// Calls a lambda each cycle (rsi::CycleMotion for the link's thread).
template <class F>
class LambdaMotion : public rsi::CycleMotion {
 public:
  explicit LambdaMotion(F& f) : f_(f) {}
  bool command(const rsi::StreamState& s, std::array<double, 6>& q) override { return f_(s, q); }

 private:
  F& f_;
};

double maxDifference(const std::array<double, 6>& a, const std::array<double, 6>& b) {
  double m = 0;
  for (size_t i = 0; i < 6; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// Six axes as seven joints (the seventh 0). Real-time safe.
JointPoint widen(const std::array<double, 6>& q) {
  JointPoint out{};
  std::copy(q.begin(), q.end(), out.begin());
  return out;
}

// How far apart the TCP is at two sets of axes (m). Real-time safe.
double tcpDistance(const model::ArmKinematics& model, const std::array<double, 6>& a, const std::array<double, 6>& b) {
  const std::array<double, 16> pa = model.GetCartPose(widen(a)), pb = model.GetCartPose(widen(b));
  return std::hypot(pa[3] - pb[3], pa[7] - pb[7], pa[11] - pb[11]);
}

// The first sample of `grid` (joints every kGridDt of plan time) the RSI session cannot follow,
// checked at the RSI cycle (rsi::JointStream::checkSample): its index and what is wrong there
// (problem empty when none is).
struct GridProblem {
  size_t sample = 0;
  std::string problem;
};
GridProblem checkGrid(const rsi::JointStream& stream, const client::JointSamples& grid,
                      const std::array<double, 6>& q_on) {
  const double dt = stream.cycleSeconds();
  const size_t stride = std::max<size_t>(1, size_t(std::lround(dt / kGridDt)));
  const std::array<double, 7>* previous = nullptr;
  for (size_t k = 0;; k = std::min(k + stride, grid.size() - 1)) {
    std::string problem =
        stream.checkSample(grid[k].data(), previous ? previous->data() : nullptr, previous ? dt : 1.0, q_on);
    if (!problem.empty()) return {k, std::move(problem)};
    previous = &grid[k];
    if (k == grid.size() - 1) return {};
  }
}

}  // namespace

RunReport Executor::run(arm::RsiArm& arm, const Program& program, const ExecutorOptions& options) {
  RsiPort port(arm.stream(), arm.digitalIo(), program.has_tool ? program.tool : kIdentityPose);
  return runOn(port, nullptr, &arm.stream(), program, options);
}

RunReport Executor::run(arm::Arm& arm, const Program& program, const ExecutorOptions& options) {
  if (auto* rsi = dynamic_cast<arm::RsiArm*>(&arm)) return run(*rsi, program, options);
  if (auto* rci = dynamic_cast<arm::RciArm*>(&arm)) return run(rci->robot(), program, options);
  throw std::invalid_argument("teach::Executor::run: an arm of neither family the executor drives (RciArm, RsiArm)");
}

void Executor::runRsiMotion(const Program& program, const Instruction& in, InstructionReport& report) {
  rsi::JointStream& stream = *stream_;
  const model::RobotSpec& spec = stream.spec();
  const model::ArmKinematics model = motionModel(program, spec, port_->toolFrame());
  const rsi::StreamState state = runningState(stream);
  std::array<double, 7> q_now{};
  for (size_t i = 0; i < 6; ++i) q_now[i] = state.q_command[i];  // where the robot is being held

  // The whole motion as joints every 1 ms of plan time.
  const double share = in.speed * kSpeedShare;
  client::JointSamples grid;
  if (in.type == InstructionType::kMoveJ) {
    std::array<double, 7> goal{};
    const int rc = jointGoal(in.target, model, q_now, goal);
    if (rc != XmateModel::kIkOk)
      throw MotionException(std::string("the target pose cannot be reached: ") + client::ikFailureText(rc) +
                            " (IK code " + std::to_string(rc) + ")");
    const planning::JointLine line = planning::planJointLine(spec, q_now, goal, share);
    const int steps = int(std::ceil(line.profile.duration / kGridDt - 1e-9));
    grid.resize(size_t(steps) + 1);
    for (int k = 0; k <= steps; ++k) planning::sampleJointLine(line, k * kGridDt, grid[size_t(k)]);
  } else {
    const planning::CartesianPath path = cartesianPath(in, model, q_now);
    client::planWithinJointLimits(typeName(in.type), path, share, model, q_now, &grid);
  }
  if (grid.empty()) grid.push_back(q_now);

  // Checked at the RSI cycle before anything moves.
  const GridProblem check = checkGrid(stream, grid, state.q_on);
  if (!check.problem.empty()) {
    char at[64];
    std::snprintf(at, sizeof at, " (at t = %.3f s of the motion)", double(check.sample) * kGridDt);
    throw MotionException(check.problem + at);
  }
  streamRsiGrid(grid, share, in.type == InstructionType::kMoveJ, model, state.session, report, nullptr);
}

void Executor::checkRsiPath(const PathTiming& timing, double rate_hz) {
  const GridProblem check = checkGrid(*stream_, timing.q, runningState(*stream_).q_on);
  if (check.problem.empty()) return;
  const double t = timing.path_time[check.sample];
  char at[96];
  std::snprintf(at, sizeof at, "at t = %.2f s of the path (near sample %ld): ", t, std::lround(t * rate_hz));
  throw MotionException(at + check.problem);
}

void Executor::streamRsiPath(const Program& program, const PathTiming& timing, PathRecording& recording,
                             InstructionReport& report) {
  const model::ArmKinematics model = motionModel(program, stream_->spec(), port_->toolFrame());
  streamRsiGrid(timing.q, kPathLimitShare, true, model, runningState(*stream_).session, report, &recording);
}

void Executor::streamRsiGrid(const client::JointSamples& grid, double share, bool joint_motion,
                             const model::ArmKinematics& model, uint32_t session, InstructionReport& report,
                             PathRecording* recording) {
  rsi::JointStream& stream = *stream_;
  const double dt = stream.cycleSeconds();
  const double total = double(grid.size() - 1) * kGridDt;
  TimeScaling scaling(override_.load(), safeScalingRate(share, accelOverVelocity(joint_motion, stream.spec())));
  const client::StallBridge::Limits limits = client::jointBridgeLimits(stream.spec(), share);
  const double braking = joint_motion ? 1.0 : kCartesianBrakingShare;
  auto planAt = [&](double t) { return samplesAt(grid, kGridDt, t); };
  double plan_time = 0, max_joint_error = 0, max_tcp_error = 0;
  uint64_t cycles = 0;
  bool stopped = false;
  std::array<double, 6> last{};
  for (size_t i = 0; i < 6; ++i) last[i] = grid.front()[i];
  auto cycle = [&](const rsi::StreamState& s, std::array<double, 6>& q) -> bool {
    ++cycles;
    max_joint_error = std::max(max_joint_error, maxDifference(s.q_command, s.q));
    max_tcp_error = std::max(max_tcp_error, tcpDistance(model, s.q_command, s.q));
    if (recording) recording->add(plan_time, widen(s.q));
    limitScalingAtPlan(scaling, plan_time, planAt, limits, 6, braking);
    scaling.setTarget(scalingTarget(scaling));
    scaling.step(dt);
    plan_time = std::min(total, plan_time + scaling.value() * dt);
    storeMotionFraction(total > 0 ? plan_time / total : 1.0);
    if (stoppedHere(scaling)) {
      stopped = true;
      q = last;
      return true;
    }
    const client::StallBridge::Vec p = planAt(plan_time);
    for (size_t i = 0; i < 6; ++i) q[i] = last[i] = p[i];
    return plan_time >= total;
  };
  LambdaMotion<decltype(cycle)> motion(cycle);
  if (total > 0) stream.run(motion, std::chrono::seconds(5), session);

  report.duration = double(cycles) * dt;
  report.max_joint_error = max_joint_error;
  report.max_tcp_error = max_tcp_error;
  if (stopped) {
    report.status = InstructionStatus::kStopped;
    report.message = "stopped by the operator";
  }
  // Settled: the actual axes have caught up with the last command.
  rsi::StreamState state;
  settle(
      [&] {
        stream.state(state);
        const double error = maxDifference(state.q_command, state.q);
        return SettleReading{error < kSettleTolerance, error, state.cycles};
      },
      dt, report);
}

}  // namespace xmate::teach
