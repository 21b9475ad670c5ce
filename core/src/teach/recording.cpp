// SPDX-License-Identifier: Apache-2.0
// Recording helpers (recording.h).
#include "teach/recording.h"

#include <Eigen/Geometry>
#include <xmate/model.h>

#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "planning/cartesian_pose.h"
#include "teach/preflight.h"

namespace xmate::teach {

Target targetFromState(const RCI::robot::RobotState& state, const model::RobotSpec& robot) {
  const bool six_axis = robot.dof == 6;
  Target t;
  t.has_q = true;
  t.q = state.q;
  if (six_axis) t.q[6] = 0;
  t.has_pose = true;
  t.pose = state.toolTobase_pos_m;
  t.has_psi = true;
  t.psi = six_axis ? 0.0 : state.psi_m;
  return t;
}

Target targetFromArm(const arm::ArmState& state, const model::RobotSpec& robot) {
  Target t;
  t.has_q = true;
  t.q = state.sample.q;
  for (size_t j = size_t(robot.dof); j < t.q.size(); ++j) t.q[j] = 0;
  t.has_pose = true;
  t.pose = state.tcp;
  t.has_psi = true;
  t.psi = 0;
  return t;
}

std::string adoptTool(Program& program, const std::array<double, 7>& q, const std::array<double, 16>& measured_tcp,
                      const std::array<double, 16>& tool, const Payload& load) {
  if (program.has_tool) {
    const ToolMismatch mismatch = toolMismatch(program, q, measured_tcp);
    return toolMatches(mismatch) ? std::string() : toolMismatchText(mismatch, program);
  }
  if (!program.instructions.empty()) return {};  // taught before tools were recorded: unknown
  Program taught = program;
  taught.has_tool = true;
  taught.tool = tool;
  if (!toolMatches(toolMismatch(taught, q, measured_tcp))) {
    const model::ArmKinematics flange_model(*program.robot);  // identity tool: the flange
    const Eigen::Isometry3d flange = planning::poseFromRowMajor(flange_model.GetCartPose(q), "flange");
    const Eigen::Isometry3d tcp = planning::poseFromRowMajor(measured_tcp, "measured TCP");
    taught.tool = planning::poseToRowMajor(flange.inverse() * tcp);
  }
  taught.load = load;
  program = std::move(taught);
  return {};
}

namespace {
Instruction motion(InstructionType type, const Target& target, double speed, std::string name) {
  Instruction in;
  in.type = type;
  in.target = target;
  in.speed = speed;
  in.name = std::move(name);
  return in;
}
}  // namespace

Instruction moveJ(const Target& target, double speed, std::string name) {
  return motion(InstructionType::kMoveJ, target, speed, std::move(name));
}

Instruction moveL(const Target& target, double speed, std::string name) {
  return motion(InstructionType::kMoveL, target, speed, std::move(name));
}

Instruction moveC(const Target& via, const Target& target, double speed, std::string name) {
  Instruction in = motion(InstructionType::kMoveC, target, speed, std::move(name));
  in.via = via;
  return in;
}

}  // namespace xmate::teach
