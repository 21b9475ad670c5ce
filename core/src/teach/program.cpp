// SPDX-License-Identifier: Apache-2.0
// Names of instruction types (program.h).
#include "teach/program.h"

namespace xmate::teach {

const char* typeName(InstructionType type) {
  switch (type) {
    case InstructionType::kMoveJ: return "MOVEJ";
    case InstructionType::kMoveL: return "MOVEL";
    case InstructionType::kMoveC: return "MOVEC";
    case InstructionType::kWait: return "WAIT";
    case InstructionType::kSetDo: return "SET_DO";
    case InstructionType::kWaitDi: return "WAIT_DI";
    case InstructionType::kPath: return "PATH";
  }
  return "?";
}

bool isMotion(InstructionType type) {
  return type == InstructionType::kMoveJ || type == InstructionType::kMoveL || type == InstructionType::kMoveC ||
         type == InstructionType::kPath;
}

std::string describe(const Program& program, size_t index) {
  std::string s = "instruction " + std::to_string(index + 1);
  if (index >= program.instructions.size()) return s;
  const Instruction& in = program.instructions[index];
  s += std::string(" (") + typeName(in.type);
  if (!in.name.empty()) s += " \"" + in.name + "\"";
  return s + ")";
}

}  // namespace xmate::teach
