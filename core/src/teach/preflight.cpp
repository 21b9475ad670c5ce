// SPDX-License-Identifier: Apache-2.0
// The pre-flight trace (preflight.h): follows the program with an offline model of the robot,
// sampling every motion in joint space (MOVEJ, a PATH's samples) or along its Cartesian path with
// chained IK (MOVEL/MOVEC), and collects every problem by instruction and what to announce.
#include "teach/preflight.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <xmate/exception.h>
#include <xmate/model.h>

#include "client/move_check.h"
#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "planning/cartesian_pose.h"
#include "teach/path.h"
#include "teach/path_timing.h"
#include "teach/program_io.h"
#include "teach/targets.h"

namespace xmate::teach {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string fmt(const char* format, double a, double b = 0, double c = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b, c);
  return buf;
}

std::string position(const std::array<double, 3>& p) { return fmt("(%.4f, %.4f, %.4f) m", p[0], p[1], p[2]); }

std::array<double, 3> translation(const std::array<double, 16>& pose) { return {pose[3], pose[7], pose[11]}; }

bool insideBox(const SafetyBox& box, const std::array<double, 3>& p) {
  const Eigen::Isometry3d frame = planning::poseFromRowMajor(box.frame, "safety box frame");
  const Eigen::Vector3d local = frame.inverse() * Eigen::Vector3d(p[0], p[1], p[2]);
  for (int i = 0; i < 3; ++i)
    if (std::abs(local[i]) > 0.5 * box.size[size_t(i)]) return false;
  return true;
}

class Tracer {
 public:
  Tracer(const Program& program, const TraceOptions& options)
      : program_(program),
        options_(options),
        spec_(*program.robot),
        model_(*program.robot),
        tool_(program.has_tool ? program.tool : options.tool) {
    model_.SetCoor(tool_);  // the TCP its poses are poses of
    model_.SetSpeedCheckInterval(0);
    if (options.has_soft_limits) {
      std::array<double, 7> up{}, low{};
      for (int i = 0; i < 7; ++i) {
        up[i] = options.soft_upper[i] * kDeg;
        low[i] = options.soft_lower[i] * kDeg;
      }
      model_.SetJointLimit(up, low);
    }
  }

  ProgramTrace run() {
    q_ = options_.q_start;
    // The measured TCP is the one at q_start: compare there, report at the first pose it concerns.
    const ToolMismatch tool = options_.has_tcp ? toolMismatch(program_, q_, options_.tcp) : ToolMismatch{};
    const bool tool_ok = toolMatches(tool);
    bool tool_reported = false;
    for (size_t i = 0; i < program_.instructions.size(); ++i) {
      index_ = i;
      current_ = InstructionTrace{};
      if (!tool_ok && !tool_reported && usesTool(program_.instructions[i])) {
        problem(toolMismatchText(tool, program_));
        tool_reported = true;  // once, at the first instruction it concerns
      }
      traceOne(program_.instructions[i]);
      current_.q_end = q_;
      result_.instructions.push_back(current_);
    }
    return result_;
  }

 private:
  const Program& program_;
  const TraceOptions& options_;
  const model::RobotSpec& spec_;
  model::ArmKinematics model_;
  std::array<double, 16> tool_;
  std::array<double, 7> q_{};
  size_t index_ = 0;
  InstructionTrace current_;
  ProgramTrace result_;

  void problem(const std::string& what) { result_.problems.push_back({index_, describe(program_, index_) + ": " + what}); }
  void notice(const std::string& what) { result_.notices.push_back({index_, describe(program_, index_) + ": " + what}); }

  void traceOne(const Instruction& in) {
    try {
      validateInstruction(in, index_, *program_.robot);
    } catch (const ProgramError& e) {
      result_.problems.push_back({index_, e.what()});
      return;
    }
    if (in.type == InstructionType::kMoveJ) traceJoint(in);
    else if (in.type == InstructionType::kPath) tracePath(in);
    else if (isMotion(in.type)) traceCartesian(in);
  }

  // Every joint within the hard range, and within the soft limits when given.
  bool withinLimits(const std::array<double, 7>& q, const char* what) {
    bool ok = true;
    for (int j = 0; j < spec_.dof; ++j) {
      if (q[j] < spec_.q_min[j] || q[j] > spec_.q_max[j]) {
        problem(std::string(what) + ": joint " + std::to_string(j + 1) + fmt(" at %.4f rad", q[j]) +
                fmt(" (%.2f deg) is outside its range [%.2f, ", q[j] * kDeg, spec_.q_min[j] * kDeg) +
                fmt("%.2f] deg; re-teach the waypoint", spec_.q_max[j] * kDeg));
        ok = false;
      } else if (options_.has_soft_limits && (q[j] < options_.soft_lower[j] || q[j] > options_.soft_upper[j])) {
        problem(std::string(what) + ": joint " + std::to_string(j + 1) + fmt(" at %.2f deg", q[j] * kDeg) +
                fmt(" is outside its soft limits [%.2f, %.2f] deg; re-teach the waypoint or widen the soft limits",
                    options_.soft_lower[j] * kDeg, options_.soft_upper[j] * kDeg));
        ok = false;
      }
    }
    return ok;
  }

  // Box checks of a sampled path: the end first (the taught target), then the way there.
  void checkBox(const std::vector<std::array<double, 3>>& path) {
    if (!options_.has_box || path.empty()) return;
    if (!insideBox(options_.box, path.back())) {
      problem("the target " + position(path.back()) +
              " is outside the Cartesian safety box; re-teach it inside the box or enlarge the box");
      return;
    }
    for (size_t k = 0; k < path.size(); ++k)
      if (!insideBox(options_.box, path[k])) {
        problem("the path leaves the Cartesian safety box at " + position(path[k]) +
                fmt(" (%.0f %% of the way); add a waypoint inside the box or use another motion type",
                    100.0 * double(k) / double(path.size() - 1)));
        return;
      }
  }

  void traceJoint(const Instruction& in) {
    std::array<double, 7> goal{};
    const int rc = jointGoal(in.target, model_, q_, goal);
    if (rc != XmateModel::kIkOk) {
      problem(std::string("the target pose cannot be reached: ") + client::ikFailureText(rc) + " (IK code " +
              std::to_string(rc) + "); re-teach it, or give the target's joint angles \"q\"");
      return;
    }
    if (!withinLimits(goal, "the target")) return;
    current_.tcp_path = jointMoveTcp(q_, goal);
    checkBox(current_.tcp_path);
    current_.traced = true;
    q_ = goal;
  }

  // The TCP along a joint move (straight in joint space), every 0.01 rad of the largest joint's
  // change.
  std::vector<std::array<double, 3>> jointMoveTcp(const std::array<double, 7>& from, const std::array<double, 7>& to) {
    const int samples = std::clamp(int(std::ceil(largestJointChange(from, to, spec_.dof) / 0.01)), 2, 1000);
    std::vector<std::array<double, 3>> tcp;
    for (int k = 0; k <= samples; ++k) {
      const double s = double(k) / samples;
      std::array<double, 7> q{};
      for (int j = 0; j < 7; ++j) q[j] = from[j] + s * (to[j] - from[j]);
      tcp.push_back(translation(model_.GetCartPose(q)));
    }
    return tcp;
  }

  // "joint 2" on an xMate, "A2" on a KUKA.
  std::string jointName(int j) const {
    return (spec_.family == model::RobotFamily::kKuka ? "A" : "joint ") + std::to_string(j + 1);
  }

  // PATH: the lead-in joint move (announced), every sample against the limits and the box, and
  // its re-timing.
  void tracePath(const Instruction& in) {
    const JointPath& path = in.path;
    const double change = largestJointChange(q_, path.q.front(), spec_.dof);
    if (change > kPathLeadIn) {
      notice(fmt("first moves to the start of the path with a joint move (largest joint change %.1f deg)",
                 change * kDeg));
      checkLeadInBox(jointMoveTcp(q_, path.q.front()));
    }
    checkPathSamples(path);
    try {
      timePath(PathSpline(path, spec_.dof), spec_, in.speed);
    } catch (const std::exception& e) {
      problem(e.what());
    }
    current_.tcp_path = tcpTrace(path, spec_, tool_);
    current_.traced = true;
    q_ = path.q.back();
  }

  void checkLeadInBox(const std::vector<std::array<double, 3>>& tcp) {
    if (!options_.has_box) return;
    for (size_t k = 0; k < tcp.size(); ++k)
      if (!insideBox(options_.box, tcp[k])) {
        problem("the joint move to the start of the path leaves the Cartesian safety box at " + position(tcp[k]) +
                fmt(" (%.0f %% of the way); add a MOVEJ inside the box before the path", 100.0 * double(k) / double(tcp.size() - 1)));
        return;
      }
  }

  // Each check names the first sample that fails it, by its time in the path.
  void checkPathSamples(const JointPath& path) {
    bool range_reported = false, soft_reported = false, bounds_reported = false, box_reported = false;
    for (size_t k = 0; k < path.q.size(); ++k) {
      const JointPoint& q = path.q[k];
      const std::string at = fmt("at t = %.3f s of the path", double(k) / path.rate_hz) + " (sample " +
                             std::to_string(k) + "): ";
      for (int j = 0; j < spec_.dof; ++j) {
        if (!range_reported && (q[j] < spec_.q_min[j] || q[j] > spec_.q_max[j])) {
          problem(at + jointName(j) + fmt(" at %.2f deg is outside its range [%.2f, %.2f] deg", q[j] * kDeg,
                                          spec_.q_min[j] * kDeg, spec_.q_max[j] * kDeg) +
                  "; record the path again within the joint range");
          range_reported = true;
        }
        if (!soft_reported && options_.has_soft_limits && (q[j] < options_.soft_lower[j] || q[j] > options_.soft_upper[j])) {
          problem(at + jointName(j) + fmt(" at %.2f deg is outside its soft limits [%.2f, %.2f] deg", q[j] * kDeg,
                                          options_.soft_lower[j] * kDeg, options_.soft_upper[j] * kDeg) +
                  "; record the path again within them or widen the soft limits");
          soft_reported = true;
        }
        if (!bounds_reported && options_.has_joint_bounds &&
            (q[j] < options_.joint_lower[j] - 1e-9 || q[j] > options_.joint_upper[j] + 1e-9)) {
          problem(at + jointName(j) + fmt(" at %.2f deg is outside what this session can reach, [%.2f, %.2f] deg",
                                          q[j] * kDeg, options_.joint_lower[j] * kDeg, options_.joint_upper[j] * kDeg) +
                  " (where RSI was switched on plus the correction limits of its context); switch RSI on nearer to "
                  "the path, raise the correction limits in the RSI context, or record the path again closer to the "
                  "RSI start pose");
          bounds_reported = true;
        }
      }
      if (!box_reported && options_.has_box) {
        const std::array<double, 3> tcp = translation(model_.GetCartPose(q));
        if (!insideBox(options_.box, tcp)) {
          problem(at + "the TCP at " + position(tcp) +
                  " is outside the Cartesian safety box; record the path again inside the box or enlarge the box");
          box_reported = true;
        }
      }
    }
  }

  void traceCartesian(const Instruction& in) {
    planning::CartesianPath path;
    try {
      path = cartesianPath(in, model_, q_);
    } catch (const std::exception& e) {
      problem(e.what());
      return;
    }
    const int samples = std::clamp(int(std::ceil(path.length / 0.002 + path.rotation_angle / 0.01 +
                                                 std::abs(path.psi_delta) / 0.01)), 2, 5000);
    std::array<double, 7> q = q_;
    for (int k = 0; k <= samples; ++k) {
      const double u = double(k) / samples;
      const planning::PathState s = planning::evaluatePath(path, u);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = s.rotation;
      pose.translation() = s.position;
      std::array<double, 7> next{};
      const int rc = model_.GetJointPos(planning::poseToRowMajor(pose), s.psi, q, next);
      if (rc != XmateModel::kIkOk) {
        problem(fmt("the path cannot be followed at %.0f %% of the way", 100 * u) + ", TCP at " +
                position({s.position.x(), s.position.y(), s.position.z()}) + ": " + client::ikFailureText(rc) +
                " (IK code " + std::to_string(rc) + "); re-teach the target or reach it with MOVEJ");
        return;
      }
      q = next;
      current_.tcp_path.push_back({s.position.x(), s.position.y(), s.position.z()});
    }
    checkBox(current_.tcp_path);
    try {
      client::planWithinJointLimits(typeName(in.type), path, in.speed * kSpeedShare, model_, q_);
    } catch (const std::exception& e) {
      problem(e.what());
      return;
    }
    current_.traced = true;
    q_ = q;
  }
};

}  // namespace

ProgramTrace traceProgram(const Program& program, const TraceOptions& options) {
  try {
    return Tracer(program, options).run();
  } catch (const std::exception& e) {
    // Bad options (a tool that is not a rigid transform, soft limits outside the joint range).
    ProgramTrace trace;
    trace.instructions.resize(program.instructions.size());
    trace.problems.push_back({0, std::string("the pre-flight cannot start: ") + e.what()});
    return trace;
  }
}

std::vector<Problem> preflight(const Program& program, const TraceOptions& options) {
  return traceProgram(program, options).problems;
}

std::vector<std::vector<std::array<double, 3>>> plannedPath(const Program& program,
                                                            const std::array<double, 7>& q_start,
                                                            const std::array<double, 16>& tool) {
  TraceOptions options;
  options.q_start = q_start;
  options.tool = tool;
  std::vector<std::vector<std::array<double, 3>>> paths;
  for (InstructionTrace& t : traceProgram(program, options).instructions)
    paths.push_back(t.traced ? std::move(t.tcp_path) : std::vector<std::array<double, 3>>{});
  return paths;
}

ToolMismatch toolMismatch(const Program& program, const std::array<double, 7>& q, const std::array<double, 16>& tcp) {
  if (!program.has_tool) return {};
  model::ArmKinematics model(*program.robot);
  model.SetCoor(program.tool);
  const Eigen::Isometry3d expected = planning::poseFromRowMajor(model.GetCartPose(q), "TCP");
  const Eigen::Isometry3d measured = planning::poseFromRowMajor(tcp, "measured TCP");
  ToolMismatch m;
  m.distance = (expected.translation() - measured.translation()).norm();
  m.angle = Eigen::AngleAxisd(expected.linear().transpose() * measured.linear()).angle();
  return m;
}

bool toolMatches(const ToolMismatch& m) { return m.distance <= kToolMismatchDistance && m.angle <= kToolMismatchAngle; }

std::string toolMismatchText(const ToolMismatch& m, const Program& program) {
  // R = Rz(rz) Ry(ry) Rx(rx), ry within +-90 deg, as the Tool & payload panel takes it.
  const auto& t = program.tool;  // row-major: R(r, c) = t[4 r + c]
  const double rx = std::atan2(t[9], t[10]), ry = std::asin(std::clamp(-t[8], -1.0, 1.0)), rz = std::atan2(t[4], t[0]);
  return fmt("the robot's tool point is %.1f mm and %.1f deg away from the one this program was taught with",
             m.distance * 1000, m.angle * kDeg) +
         fmt(" (x, y, z = %.4f, %.4f, %.4f m", program.tool[3], program.tool[7], program.tool[11]) +
         fmt("; rx, ry, rz = %.2f, %.2f, %.2f deg; at most 1 mm and 0.5 deg allowed): ", rx * kDeg + 0.0,
             ry * kDeg + 0.0, rz * kDeg + 0.0) +
         "set the tool and load the program was taught with, or teach the program again with this tool";
}

bool usesTool(const Instruction& in) {
  if (in.type == InstructionType::kMoveL || in.type == InstructionType::kMoveC) return true;
  return in.type == InstructionType::kMoveJ && !in.target.has_q;
}

std::string problemsText(const std::vector<Problem>& problems) {
  std::string s;
  for (const Problem& p : problems) s += p.message + "\n";
  return s;
}

}  // namespace xmate::teach
