// SPDX-License-Identifier: Apache-2.0
// The digital signals of each robot family by name (signal_names.h).
#include "model/signal_names.h"

namespace xmate::model {
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

std::string nameOf(RobotFamily family, int index, const char* const (&xmate)[kXmateSignalCount],
                   const char* kuka) {
  if (family == RobotFamily::kKuka)
    return index >= 1 && index <= kKukaSignalCount ? kuka + std::to_string(index) + "]" : "?";
  return index >= 0 && index < kXmateSignalCount ? xmate[index] : "?";
}

}  // namespace

std::string doName(RobotFamily family, int index) { return nameOf(family, index, kDo, "$OUT["); }
std::string diName(RobotFamily family, int index) { return nameOf(family, index, kDi, "$IN["); }
int doIndex(RobotFamily family, const std::string& name) {
  return family == RobotFamily::kKuka ? kukaIndex("$OUT[", name) : indexIn(kDo, name);
}
int diIndex(RobotFamily family, const std::string& name) {
  return family == RobotFamily::kKuka ? kukaIndex("$IN[", name) : indexIn(kDi, name);
}

std::string knownSignals(RobotFamily family, bool output) {
  if (family == RobotFamily::kKuka) return output ? "$OUT[1] to $OUT[4096]" : "$IN[1] to $IN[4096]";
  std::string list;
  for (const char* name : output ? kDo : kDi) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

}  // namespace xmate::model
