// SPDX-License-Identifier: Apache-2.0
// rci-cli: headless tools for xMate robots (docs/client.md). Without arguments it describes the
// default model; subcommands read a robot's state live, check the machine's real-time setup, and
// benchmark the 1 kHz loop and the client's cost per cycle, and run taught programs headless.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <xmate/exception.h>

#include "cli.h"

int main(int argc, char** argv) {
  using namespace rci_cli;
  std::vector<std::string> words(argv + 1, argv + argc);
  try {
    if (words.empty()) return runModel(Args({}));
    const std::string command = words[0];
    if (command == "help" || command == "--help" || command == "-h") {
      std::fputs(usage().c_str(), stdout);
      return 0;
    }
    if (command == "model") return runModel(Args({words.begin() + 1, words.end()}));
    if (command == "state") return runState(Args({words.begin() + 1, words.end()}));
    if (command == "run") return runRun(Args({words.begin() + 1, words.end()}));
    if (command == "doctor") return runDoctor(Args({words.begin() + 1, words.end()}));
    if (command == "bench") {
      if (words.size() < 2) throw UsageError("bench needs 'loop' or 'client'");
      if (words[1] == "loop") return runBenchLoop(Args({words.begin() + 2, words.end()}));
      if (words[1] == "client") return runBenchClient(Args({words.begin() + 2, words.end()}));
      throw UsageError("unknown bench '" + words[1] + "' (known: loop, client)");
    }
    throw UsageError("unknown command '" + command + "'");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "rci-cli: %s\n\n%s", e.what(), usage().c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rci-cli: %s\n", e.what());
    return 1;
  }
}
