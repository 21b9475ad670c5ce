// SPDX-License-Identifier: Apache-2.0
// The executor's port to a KUKA over RSI (rsi_port.h): every motion becomes joints every 1 ms of plan time
// -- MOVEJ from planning::JointLine, MOVEL/MOVEC through IK of the timed Cartesian path, a PATH
// from its re-timing (executor_path.cpp) -- checked at the RSI cycle against the axis ranges,
// speeds and the context's AXISCORR limits before it starts, then streamed one command per RSI
// cycle by arm::JointStream. The plan time advances by k * cycle as on the xMate, so pause, stop and
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
#include "rsi/digital_io.h"
#include "arm/joint_stream.h"
#include "teach/executor.h"
#include "teach/executor_path.h"
#include "teach/path_timing.h"
#include "teach/plan_scaling.h"
#include "teach/settle.h"
#include "teach/rsi_port.h"
#include "teach/targets.h"

namespace xmate::teach {
namespace {

constexpr double kGridDt = 1e-3;  // plan time between two precomputed joint samples

// The stream's newest state; MotionException when RSI is not running (no <Rob> yet).
arm::StreamState runningState(const arm::JointStream& stream) {
  arm::StreamState state;
  if (!stream.state(state)) throw MotionException("RSI is not running: start the KRL program on the robot");
  return state;
}

// Calls a lambda each cycle (an arm::JointMotion for the link's thread).
template <class F>
class LambdaMotion : public arm::JointMotion {
 public:
  explicit LambdaMotion(F& f) : f_(f) {}
  bool command(const arm::ArmSample& s, std::array<double, 7>& q) override { return f_(s, q); }

 private:
  F& f_;
};

// The largest difference of the six axes. Real-time safe.
double maxDifference(const std::array<double, 7>& a, const std::array<double, 7>& b) {
  double m = 0;
  for (size_t i = 0; i < 6; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// How far apart the TCP is at two sets of axes (m). Real-time safe.
double tcpDistance(const model::ArmKinematics& model, const std::array<double, 7>& a, const std::array<double, 7>& b) {
  const std::array<double, 16> pa = model.GetCartPose(a), pb = model.GetCartPose(b);
  return std::hypot(pa[3] - pb[3], pa[7] - pb[7], pa[11] - pb[11]);
}

// Six axes as seven joints (the seventh 0).
JointPoint widen(const std::array<double, 6>& q) {
  JointPoint out{};
  std::copy(q.begin(), q.end(), out.begin());
  return out;
}

// The first sample of `grid` (joints every kGridDt of plan time) the RSI session cannot follow,
// checked at the RSI cycle (arm::JointStream::checkSample): its index and what is wrong there
// (problem empty when none is).
struct GridProblem {
  size_t sample = 0;
  std::string problem;
};
GridProblem checkGrid(const arm::JointStream& stream, const client::JointSamples& grid,
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

RsiPort::RsiPort(arm::JointStream& stream, rsi::DigitalIo* io, const std::array<double, 16>& tool)
    : stream_(stream), io_(io), model_(stream.spec()), tool_(tool) {
  model_.SetCoor(tool);
}

const model::RobotSpec& RsiPort::spec() const { return stream_.spec(); }

RobotPort::Reading RsiPort::read() {
  arm::StreamState s;
  if (!stream_.state(s))
    throw std::runtime_error("RSI is not running: no <Rob> datagram has arrived; start the KRL program (RSI_ON, "
                             "RSI_MOVECORR) on the robot");
  Reading r;
  for (size_t i = 0; i < 6; ++i) r.q[i] = s.q[i];
  r.tcp = model_.GetCartPose(r.q);
  return r;
}

void RsiPort::setDO(int signal, bool value) { io().setOutput(signal, value); }

bool RsiPort::getDI(int signal) { return io().input(signal); }

bool RsiPort::reachableBounds(std::array<double, 7>& lower, std::array<double, 7>& upper) {
  return stream_.reachableBounds(lower, upper);
}

rsi::DigitalIo& RsiPort::io() {
  if (!io_)
    throw std::runtime_error("the RSI context wires no digital inputs or outputs to the PC: wire DIGIN / DIGOUT "
                             "objects to the ETHERNET object (as resources/rsi/rci_replay.rsi.xml does), or "
                             "remove SET_DO and WAIT_DI from the program");
  return *io_;
}

void RsiPort::move(const Program& program, const Instruction& in, const model::ArmKinematics& model,
                   MotionControl& control, InstructionReport& report) {
  (void)program;  // RSI does not tell the tool: the port's is the program's
  arm::JointStream& stream = stream_;
  const model::RobotSpec& spec = stream.spec();
  const arm::StreamState state = runningState(stream);
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
  streamGrid(grid, share, in.type == InstructionType::kMoveJ, model, state.session, control, report, nullptr);
}

void RsiPort::checkPath(const PathTiming& timing, double rate_hz) {
  const GridProblem check = checkGrid(stream_, timing.q, runningState(stream_).q_on);
  if (check.problem.empty()) return;
  const double t = timing.path_time[check.sample];
  char at[96];
  std::snprintf(at, sizeof at, "at t = %.2f s of the path (near sample %ld): ", t, std::lround(t * rate_hz));
  throw MotionException(at + check.problem);
}

void RsiPort::streamPath(const JointPath& path, const PathTiming& timing, const model::ArmKinematics& model,
                         MotionControl& control, PathRecording& recording, InstructionReport& report) {
  (void)path;  // checked in checkPath against what the session can reach
  streamGrid(timing.q, kPathLimitShare, true, model, runningState(stream_).session, control, report, &recording);
}

void RsiPort::streamGrid(const client::JointSamples& grid, double share, bool joint_motion,
                         const model::ArmKinematics& model, uint32_t session, MotionControl& control,
                         InstructionReport& report, PathRecording* recording) {
  arm::JointStream& stream = stream_;
  const double dt = stream.cycleSeconds();
  const double total = double(grid.size() - 1) * kGridDt;
  TimeScaling scaling(control.speedOverride(), safeScalingRate(share, accelOverVelocity(joint_motion, stream.spec())));
  const client::StallBridge::Limits limits = client::jointBridgeLimits(stream.spec(), share);
  const double braking = joint_motion ? 1.0 : kCartesianBrakingShare;
  auto planAt = [&](double t) { return samplesAt(grid, kGridDt, t); };
  double plan_time = 0, max_joint_error = 0, max_tcp_error = 0;
  uint64_t cycles = 0;
  bool stopped = false;
  std::array<double, 7> last = grid.front();
  auto cycle = [&](const arm::ArmSample& s, std::array<double, 7>& q) -> bool {
    ++cycles;
    max_joint_error = std::max(max_joint_error, maxDifference(s.q_command, s.q));
    max_tcp_error = std::max(max_tcp_error, tcpDistance(model, s.q_command, s.q));
    if (recording) recording->add(plan_time, s.q);
    limitScalingAtPlan(scaling, plan_time, planAt, limits, 6, braking);
    scaling.setTarget(control.scalingTarget(scaling));
    scaling.step(dt);
    plan_time = std::min(total, plan_time + scaling.value() * dt);
    control.storeFraction(total > 0 ? plan_time / total : 1.0);
    if (control.stoppedHere(scaling)) {
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
  arm::StreamState state;
  settle(
      [&] {
        stream.state(state);
        const double error = maxDifference(widen(state.q_command), widen(state.q));
        return SettleReading{error < kSettleTolerance, error, state.cycles};
      },
      dt, report);
}

}  // namespace xmate::teach
