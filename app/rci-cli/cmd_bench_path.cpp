// SPDX-License-Identifier: Apache-2.0
// rci-cli bench path: what turning a demonstration into a replay plan costs -- reducing a 1 kHz
// recording to its stored rate, and re-timing the stored path within the joint limits -- on a
// generated hand-guided motion, against writing the same recording as JSON text, measured in the
// same run (docs/performance.md, "Teach by demonstration").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "model/robot_spec.h"
#include "teach/path.h"
#include "teach/path_timing.h"
#include "teach/program_io.h"

namespace rci_cli {
namespace {

using namespace xmate;
using Clock = std::chrono::steady_clock;

// An operator guiding an xMate Pro 7 for `seconds`: from rest, every joint swinging with a few
// incommensurate sines (peak speeds 0.3 to 0.9 rad/s), back to rest. `pace` > 1 goes through the
// same motion that many times faster (in seconds / pace).
std::vector<teach::JointPoint> handGuided(double seconds, double rate, double pace = 1) {
  std::vector<teach::JointPoint> q;
  const size_t n = size_t(std::lround(seconds * rate)) + 1;  // the recording's samples
  q.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    const double x = double(k) / double(n - 1);
    const double s = x * x * x * (10 - 15 * x + 6 * x * x) * seconds * pace;  // with rest at both ends
    q.push_back({0.4 * std::sin(0.9 * s) + 0.05 * std::sin(3.1 * s), 0.4 + 0.3 * std::sin(0.6 * s),
                 0.25 * std::cos(1.2 * s) - 0.25, 1.2 + 0.35 * std::sin(0.45 * s + 0.3 * std::sin(2.2 * s)),
                 0.2 * std::sin(1.4 * s), 0.9 + 0.25 * std::sin(0.8 * s), 0.3 * std::sin(0.35 * s)});
  }
  return q;
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int runBenchPath(double seconds, int rounds) {
  const model::RobotSpec& spec = model::robotSpec(XMATE7_PRO);
  const double rate = 1000;
  const std::vector<teach::JointPoint> recording = handGuided(seconds, rate);
  std::printf("rci-cli bench path: a %.0f s hand-guided motion recorded at %.0f Hz (%zu samples, %s), %d rounds, "
              "medians\n",
              seconds, rate, recording.size(), std::string(spec.display_name).c_str(), rounds);

  // The motion four times as fast over the same time (four times the swings): beyond the joints'
  // limits, so the re-timing slows it where needed (more rounds of checking).
  const std::vector<teach::JointPoint> fast = handGuided(seconds, rate, 4);
  std::vector<double> reference, reduce, retime, fast_total;
  teach::Reduction reduced;
  teach::PathTiming timing, fast_timing;
  size_t json_bytes = 0;
  for (int r = 0; r < rounds; ++r) {
    // Reference: the raw recording written as JSON text (what storing it unreduced would cost).
    auto start = Clock::now();
    json_bytes = nlohmann::json(recording).dump().size();
    reference.push_back(millisecondsSince(start));

    start = Clock::now();
    reduced = teach::reducePath(recording, rate, spec.dof);
    reduce.push_back(millisecondsSince(start));

    start = Clock::now();
    const teach::PathSpline spline(reduced.path, spec.dof);
    timing = teach::timePath(spline, spec, 1.0);
    retime.push_back(millisecondsSince(start));

    start = Clock::now();
    const teach::Reduction fast_reduced = teach::reducePath(fast, rate, spec.dof);
    fast_timing = teach::timePath(teach::PathSpline(fast_reduced.path, spec.dof), spec, 1.0);
    fast_total.push_back(millisecondsSince(start));
  }

  teach::Program program;
  program.robot = &spec;
  teach::Instruction in;
  in.type = teach::InstructionType::kPath;
  in.name = "bench";
  in.path = reduced.path;
  in.speed = 1.0;
  program.instructions.push_back(in);
  const size_t program_bytes = teach::programText(program).size();

  const double ref = median(reference), red = median(reduce), ret = median(retime);
  std::printf("  %-58s %9.2f ms  (1.00x)\n", "reference: the recording as JSON text (nlohmann-json)", ref);
  std::printf("  %-58s %9.2f ms  (%.2fx)\n", "reduce: 1 kHz recording -> stored path", red, red / ref);
  std::printf("  %-58s %9.2f ms  (%.2fx)\n", "re-time: stored path -> 1 ms replay plan", ret, ret / ref);
  std::printf("  %-58s %9.2f ms  (%.2fx)\n", "reduce + re-time", red + ret, (red + ret) / ref);
  const double fst = median(fast_total);
  char label[80];
  std::snprintf(label, sizeof label, "reduce + re-time, 4x as fast (beyond the limits: slowed)");
  std::printf("  %-58s %9.2f ms  (%.2fx)\n", label, fst, fst / ref);
  std::printf("stored at %.0f Hz: %zu samples, largest error %.1f urad (bound %.0f urad); program file %.0f kB "
              "(the raw recording as JSON: %.0f kB)\n",
              reduced.path.rate_hz, reduced.path.q.size(), reduced.max_error * 1e6, teach::kPathTolerance * 1e6,
              double(program_bytes) / 1000, double(json_bytes) / 1000);
  std::printf("replay plan: %.2f s for %.2f s demonstrated (%zu samples), slowest pace %.0f %% of the demonstration\n",
              timing.duration, timing.nominal_duration, timing.q.size(), timing.slowest * 100);
  std::printf("too fast: %.2f s for %.2f s demonstrated, slowed to %.0f %% at worst, %.0f %% of it slowed\n",
              fast_timing.duration, fast_timing.nominal_duration, fast_timing.slowest * 100,
              fast_timing.slowed_share * 100);
  return 0;
}

}  // namespace rci_cli
