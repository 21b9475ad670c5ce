// SPDX-License-Identifier: Apache-2.0
// The executor's PATH (executor.h, docs/teach.md "Replaying a path"), on either robot family: the
// path re-timed within the limits (timePath), checked by the port (on a KUKA: against what the RSI
// session can reach), then a lead-in joint move to its first sample, then the timing streamed with the same
// plan-time machinery as every motion (pause, stop, override, single step), and afterwards the
// measured joints compared with the path (pathDeviation).
#include <algorithm>
#include <cmath>

#include "planning/joint_line.h"
#include "teach/executor.h"
#include "teach/executor_path.h"
#include "teach/path.h"
#include "teach/path_timing.h"
#include "teach/robot_port.h"
#include "teach/targets.h"

namespace xmate::teach {

PathRecording::PathRecording(const PathTiming& timing) : timing_(timing) {
  measured_.reserve(timing.q.size() + 1);
  hints_.reserve(timing.q.size() + 1);
}

void PathRecording::add(double plan_time, const JointPoint& measured) {
  if (plan_time < next_plan_time_ || measured_.size() == measured_.capacity()) return;
  next_plan_time_ = plan_time + timing_.step;
  // The path time the plan commanded: path_time between the two samples around plan_time.
  const size_t last = timing_.path_time.size() - 1;
  const double x = std::clamp(plan_time / timing_.step, 0.0, double(last));
  const size_t i = std::min(size_t(x), last);
  const size_t j = std::min(i + 1, last);
  const double f = x - double(i);
  measured_.push_back(measured);
  hints_.push_back(timing_.path_time[i] + f * (timing_.path_time[j] - timing_.path_time[i]));
}

void Executor::runPath(const Program& program, size_t index, InstructionReport& report) {
  const Instruction& in = program.instructions[index];
  const model::RobotSpec& spec = port_->spec();
  const PathSpline spline(in.path, spec.dof);
  const PathTiming timing = timePath(spline, spec, in.speed);  // throws, in operator words, when impossible
  report.nominal_duration = timing.nominal_duration;
  report.slowest_pace = timing.slowest;
  report.slowed_share = timing.slowed_share;
  report.slowest_at = timing.slowest_at;
  port_->checkPath(timing, in.path.rate_hz);  // before anything moves

  // One progress for the instruction: the lead-in's share of it as long as its joint move takes
  // (the same planner as the move itself), the path the rest.
  struct WholeProgress {
    double& from;
    double& span;
    ~WholeProgress() { from = 0, span = 1; }
  } whole{fraction_from_, fraction_span_};
  const JointPoint q_now = port_->read().q;
  const bool lead_in = largestJointChange(q_now, in.path.q.front(), spec.dof) > kPathLeadIn;
  const double lead =
      lead_in ? planning::planJointLine(spec, q_now, in.path.q.front(), in.speed * kSpeedShare).profile.duration : 0.0;
  fraction_span_ = lead + timing.duration > 0 ? lead / (lead + timing.duration) : 0.0;
  if (lead_in && !leadIn(program, in, report)) return;
  fraction_from_ = fraction_span_;
  fraction_span_ = 1 - fraction_from_;

  PathRecording recording(timing);
  const model::ArmKinematics model = motionModel(program);
  port_->streamPath(in.path, timing, model, *this, recording, report);
  if (recording.measured().empty()) return;
  const PathDeviation deviation = pathDeviation(spline, model, recording.measured(), recording.hints());
  report.path_joint_deviation = deviation.joint;
  report.path_tcp_deviation = deviation.tcp;
}

bool Executor::leadIn(const Program& program, const Instruction& in, InstructionReport& report) {
  const JointPoint& start = in.path.q.front();
  Instruction move;  // a MOVEJ to the first sample, at the PATH's speed
  move.type = InstructionType::kMoveJ;
  move.name = in.name;
  move.target.has_q = true;
  move.target.q = start;
  move.speed = in.speed;
  InstructionReport lead;
  lead.status = InstructionStatus::kRunning;
  runMotion(program, move, lead);
  report.lead_in = lead.duration;
  if (lead.status != InstructionStatus::kStopped) return true;
  report.status = InstructionStatus::kStopped;
  report.message = "stopped by the operator on the way to the start of the path";
  report.max_joint_error = lead.max_joint_error;
  report.max_tcp_error = lead.max_tcp_error;
  report.settle_time = lead.settle_time;
  report.settled = lead.settled;
  report.settle_error = lead.settle_error;
  return false;
}

}  // namespace xmate::teach
