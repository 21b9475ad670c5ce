// SPDX-License-Identifier: Apache-2.0
// Names of instruction types and IO signals (program.h).
#include "teach/program.h"

namespace xmate::teach {
namespace {

constexpr const char* kDo[kSignalCount] = {"DO0_0", "DO0_1", "DO0_2", "DO0_3", "DO1_0", "DO1_1"};
constexpr const char* kDi[kSignalCount] = {"DI0_0", "DI0_1", "DI0_2", "DI0_3", "DI1_0", "DI1_1"};

int indexIn(const char* const (&names)[kSignalCount], const std::string& name) {
  for (int i = 0; i < kSignalCount; ++i)
    if (name == names[i]) return i;
  return -1;
}

}  // namespace

const char* typeName(InstructionType type) {
  switch (type) {
    case InstructionType::kMoveJ: return "MOVEJ";
    case InstructionType::kMoveL: return "MOVEL";
    case InstructionType::kMoveC: return "MOVEC";
    case InstructionType::kWait: return "WAIT";
    case InstructionType::kSetDo: return "SET_DO";
    case InstructionType::kWaitDi: return "WAIT_DI";
  }
  return "?";
}

bool isMotion(InstructionType type) {
  return type == InstructionType::kMoveJ || type == InstructionType::kMoveL || type == InstructionType::kMoveC;
}

const char* doName(int index) { return index >= 0 && index < kSignalCount ? kDo[index] : "?"; }
const char* diName(int index) { return index >= 0 && index < kSignalCount ? kDi[index] : "?"; }
int doIndex(const std::string& name) { return indexIn(kDo, name); }
int diIndex(const std::string& name) { return indexIn(kDi, name); }

std::string describe(const Program& program, size_t index) {
  std::string s = "instruction " + std::to_string(index + 1);
  if (index >= program.instructions.size()) return s;
  const Instruction& in = program.instructions[index];
  s += std::string(" (") + typeName(in.type);
  if (!in.name.empty()) s += " \"" + in.name + "\"";
  return s + ")";
}

}  // namespace xmate::teach
