// SPDX-License-Identifier: Apache-2.0
// Run report -> JSON (report.h).
#include "teach/report.h"

#include "model/robot_spec.h"
#include "teach/atomic_file.h"
#include "teach/json_text.h"

namespace xmate::teach {
namespace {

Json instructionJson(const Program& program, size_t i, const InstructionReport& r) {
  const Instruction& in = program.instructions[i];
  Json v = Json::object();
  v["index"] = i + 1;
  v["type"] = typeName(in.type);
  if (!in.name.empty()) v["name"] = in.name;
  v["status"] = statusName(r.status);
  if (!r.message.empty()) v["message"] = r.message;
  if (r.status != InstructionStatus::kNotRun) {
    v["duration_s"] = r.duration;
    v["q"] = r.q;
    v["pose"] = r.pose;
    v["psi"] = r.psi;
  }
  if (isMotion(in.type) && r.status != InstructionStatus::kNotRun) {
    v["max_joint_error_rad"] = r.max_joint_error;
    v["max_tcp_error_m"] = r.max_tcp_error;
    v["settle_s"] = r.settle_time;
    v["settled"] = r.settled;
    if (!r.settled) v["settle_error_rad"] = r.settle_error;
  }
  return v;
}

}  // namespace

Json reportToJson(const Program& program, const RunReport& report) {
  Json doc = Json::object();
  doc["format"] = kReportFormat;
  doc["version"] = 1;
  doc["robot"] = std::string(program.robot->name);
  doc["outcome"] = runStateName(report.outcome);
  if (!report.message.empty()) doc["message"] = report.message;
  doc["failed_instruction"] = report.failed_instruction >= 0 ? Json(report.failed_instruction + 1) : Json();
  doc["duration_s"] = report.duration;
  Json problems = Json::array();
  for (const Problem& p : report.problems) {
    Json v = Json::object();
    v["instruction"] = p.instruction + 1;
    v["message"] = p.message;
    problems.push_back(std::move(v));
  }
  doc["problems"] = std::move(problems);
  Json list = Json::array();
  for (size_t i = 0; i < report.instructions.size() && i < program.instructions.size(); ++i)
    list.push_back(instructionJson(program, i, report.instructions[i]));
  doc["instructions"] = std::move(list);
  return doc;
}

std::string reportText(const Program& program, const RunReport& report) {
  return jsonText(reportToJson(program, report));
}

void saveReport(const std::string& path, const Program& program, const RunReport& report) {
  writeFileAtomically(path, reportText(program, report));
}

}  // namespace xmate::teach
