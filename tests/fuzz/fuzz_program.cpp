// SPDX-License-Identifier: Apache-2.0
// libFuzzer target of the program loader (teach/program_io.h on nlohmann-json): any bytes either
// load as a program or are refused with a ProgramError -- never another exception, a crash or a
// sanitizer report -- and a program that loads saves to a text that loads back to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "teach/program_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace xmate::teach;
  Program program;
  try {
    program = parseProgram(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const ProgramError&) {
    return 0;
  }
  const std::string saved = programText(program);
  if (programText(parseProgram(saved)) != saved) std::abort();
  return 0;
}
