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
  if (in.type == InstructionType::kPath && r.status != InstructionStatus::kNotRun) {
    v["lead_in_s"] = r.lead_in;
    v["nominal_duration_s"] = r.nominal_duration;
    v["path_joint_deviation_rad"] = r.path_joint_deviation;
    v["path_tcp_deviation_m"] = r.path_tcp_deviation;
    v["slowest_pace"] = r.slowest_pace;
    v["slowed_share"] = r.slowed_share;
    v["slowest_at_s"] = r.slowest_at;
  }
  return v;
}

// Pre-flight problems and notices alike: the instruction (1-based) and the message.
Json problemsJson(const std::vector<Problem>& problems) {
  Json list = Json::array();
  for (const Problem& p : problems) {
    Json v = Json::object();
    v["instruction"] = p.instruction + 1;
    v["message"] = p.message;
    list.push_back(std::move(v));
  }
  return list;
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
  doc["problems"] = problemsJson(report.problems);
  doc["notices"] = problemsJson(report.notices);
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
