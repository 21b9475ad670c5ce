// SPDX-License-Identifier: Apache-2.0
// rci-cli bench soak: the soak of soak/soak.h -- hundreds of mixed motions against the in-process
// simulator on its real-time clock while it loses states at random and two threads burn CPU --
// with progress on stderr and the figures per motion kind on stdout (a table, or JSON).
#include <cstdio>

#include "cli.h"
#include "soak/soak.h"

namespace rci_cli {
namespace {

constexpr long kProgressEvery = 20;  // motions

// On stderr, so that stdout keeps only the report: each failure as it happens, and a line now and then.
void printProgress(const soak::MotionResult& r, long motions, long& failures) {
  if (r.recovery) {
    if (r.failed) std::fprintf(stderr, "  the move to motion %ld's start failed: %s\n", r.index + 1, r.failure.c_str());
    return;
  }
  if (r.failed) {
    ++failures;
    std::fprintf(stderr, "  motion %ld (%s) failed: %s\n", r.index + 1, soak::kindName(r.kind), r.failure.c_str());
  }
  if ((r.index + 1) % kProgressEvery == 0 || r.index + 1 == motions)
    std::fprintf(stderr, "  %ld of %ld motions, %ld failed\n", r.index + 1, motions, failures);
}

}  // namespace

int runBenchSoak(const soak::SoakOptions& options, bool json) {
  long failures = 0;
  std::fprintf(stderr, "rci-cli bench soak: %ld motions; the figures follow at the end\n", options.motions);
  const soak::SoakReport report =
      soak::runSoak(options, [&](const soak::MotionResult& r) { printProgress(r, options.motions, failures); });
  const std::string text = json ? soak::reportJson(report) + "\n" : soak::reportText(report);
  std::fputs(text.c_str(), stdout);
  return report.failures() > 0 ? 1 : 0;
}

}  // namespace rci_cli
