// SPDX-License-Identifier: Apache-2.0
// The run report as JSON (docs/teach.md, "Report"): the outcome, the failing instruction, the
// pre-flight problems and notices, and per instruction its status, reached q and pose, duration and
// maximum tracking error (a PATH also its lead-in, deviation from the path and how much it was
// slowed). rci-cli run --report writes it; the GUI can save it the same way.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "teach/executor.h"
#include "teach/program.h"

namespace xmate::teach {

inline constexpr const char* kReportFormat = "rci-run-report";

nlohmann::ordered_json reportToJson(const Program& program, const RunReport& report);
// The report as indented JSON text (teach/json_text.h), as saveReport writes it.
std::string reportText(const Program& program, const RunReport& report);

// Writes the report atomically (atomic_file.h); std::runtime_error on failure.
void saveReport(const std::string& path, const Program& program, const RunReport& report);

}  // namespace xmate::teach
