// SPDX-License-Identifier: Apache-2.0
// Run report -> JSON (report.h).
#include "teach/report.h"

#include "model/robot_spec.h"
#include "teach/atomic_file.h"

namespace xmate::teach {
namespace {

JsonValue instructionJson(const Program& program, size_t i, const InstructionReport& r) {
  const Instruction& in = program.instructions[i];
  JsonValue v = JsonValue::object();
  v.set("index", JsonValue::number(double(i + 1)));
  v.set("type", JsonValue::string(typeName(in.type)));
  if (!in.name.empty()) v.set("name", JsonValue::string(in.name));
  v.set("status", JsonValue::string(statusName(r.status)));
  if (!r.message.empty()) v.set("message", JsonValue::string(r.message));
  if (r.status != InstructionStatus::kNotRun) {
    v.set("duration_s", JsonValue::number(r.duration));
    v.set("q", JsonValue::numbers(r.q.data(), r.q.size()));
    v.set("pose", JsonValue::numbers(r.pose.data(), r.pose.size()));
    v.set("psi", JsonValue::number(r.psi));
  }
  if (isMotion(in.type) && r.status != InstructionStatus::kNotRun) {
    v.set("max_joint_error_rad", JsonValue::number(r.max_joint_error));
    v.set("max_tcp_error_m", JsonValue::number(r.max_tcp_error));
  }
  return v;
}

}  // namespace

JsonValue reportToJson(const Program& program, const RunReport& report) {
  JsonValue doc = JsonValue::object();
  doc.set("format", JsonValue::string(kReportFormat));
  doc.set("version", JsonValue::number(1));
  doc.set("robot", JsonValue::string(std::string(model::robotSpec(program.robot).name)));
  doc.set("outcome", JsonValue::string(runStateName(report.outcome)));
  if (!report.message.empty()) doc.set("message", JsonValue::string(report.message));
  doc.set("failed_instruction",
          report.failed_instruction >= 0 ? JsonValue::number(double(report.failed_instruction + 1)) : JsonValue());
  doc.set("duration_s", JsonValue::number(report.duration));
  JsonValue problems = JsonValue::array();
  for (const Problem& p : report.problems) {
    JsonValue v = JsonValue::object();
    v.set("instruction", JsonValue::number(double(p.instruction + 1)));
    v.set("message", JsonValue::string(p.message));
    problems.push(std::move(v));
  }
  doc.set("problems", std::move(problems));
  JsonValue list = JsonValue::array();
  for (size_t i = 0; i < report.instructions.size() && i < program.instructions.size(); ++i)
    list.push(instructionJson(program, i, report.instructions[i]));
  doc.set("instructions", std::move(list));
  return doc;
}

void saveReport(const std::string& path, const Program& program, const RunReport& report) {
  writeFileAtomically(path, writeJson(reportToJson(program, report)));
}

}  // namespace xmate::teach
