// SPDX-License-Identifier: Apache-2.0
// Names of instruction types and IO signals (program.h).
#include "teach/program.h"

namespace xmate::teach {
namespace {

constexpr const char* kDo[kXmateSignalCount] = {"DO0_0", "DO0_1", "DO0_2", "DO0_3", "DO1_0", "DO1_1"};
constexpr const char* kDi[kXmateSignalCount] = {"DI0_0", "DI0_1", "DI0_2", "DI0_3", "DI1_0", "DI1_1"};

int indexIn(const char* const (&names)[kXmateSignalCount], const std::string& name) {
  for (int i = 0; i < kXmateSignalCount; ++i)
    if (name == names[i]) return i;
  return -1;
}

// "$OUT[12]" -> 12 (prefix "$OUT["), -1 unless it is exactly that form with n in 1..4096.
int kukaIndex(const std::string& prefix, const std::string& name) {
  if (name.size() <= prefix.size() + 1 || name.compare(0, prefix.size(), prefix) != 0 || name.back() != ']') return -1;
  int n = 0;
  for (size_t i = prefix.size(); i + 1 < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9' || n > kKukaSignalCount) return -1;
    n = n * 10 + (name[i] - '0');
  }
  return n >= 1 && n <= kKukaSignalCount && name[prefix.size()] != '0' ? n : -1;
}

std::string nameOf(model::RobotFamily family, int index, const char* const (&xmate)[kXmateSignalCount],
                   const char* kuka) {
  if (family == model::RobotFamily::kKuka)
    return index >= 1 && index <= kKukaSignalCount ? kuka + std::to_string(index) + "]" : "?";
  return index >= 0 && index < kXmateSignalCount ? xmate[index] : "?";
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

std::string doName(model::RobotFamily family, int index) { return nameOf(family, index, kDo, "$OUT["); }
std::string diName(model::RobotFamily family, int index) { return nameOf(family, index, kDi, "$IN["); }
int doIndex(model::RobotFamily family, const std::string& name) {
  return family == model::RobotFamily::kKuka ? kukaIndex("$OUT[", name) : indexIn(kDo, name);
}
int diIndex(model::RobotFamily family, const std::string& name) {
  return family == model::RobotFamily::kKuka ? kukaIndex("$IN[", name) : indexIn(kDi, name);
}

std::string knownSignals(model::RobotFamily family, bool output) {
  if (family == model::RobotFamily::kKuka) return output ? "$OUT[1] to $OUT[4096]" : "$IN[1] to $IN[4096]";
  std::string list;
  for (const char* name : output ? kDo : kDi) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
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
