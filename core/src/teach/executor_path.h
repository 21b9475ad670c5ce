// SPDX-License-Identifier: Apache-2.0
// Internal to the executor and its ports (executor_path.cpp, rci_port.cpp, rsi_port.cpp): what a PATH
// replay records on the real-time thread -- the measured joints and the path time the plan
// commanded then -- into storage reserved before the motion, for pathDeviation afterwards.
#pragma once

#include <cstddef>
#include <vector>

#include "teach/path_timing.h"

namespace xmate::teach {

class PathRecording {
 public:
  // Reserves one sample per step of the timing's plan time (allocates: call before the motion).
  // `timing` must outlive the recording.
  explicit PathRecording(const PathTiming& timing);

  // The real-time thread, each cycle: the joints measured while the plan stood at `plan_time` (s
  // of the timing). Keeps at most one sample per step of plan time (a slow override or a pause adds
  // none) and ignores what comes once the reserved room is full. No allocation, no lock.
  void add(double plan_time, const JointPoint& measured);

  // After the motion: the measured joints and, for each, the path time (s of the demonstration)
  // the plan commanded then.
  const std::vector<JointPoint>& measured() const { return measured_; }
  const std::vector<double>& hints() const { return hints_; }

 private:
  const PathTiming& timing_;
  std::vector<JointPoint> measured_;
  std::vector<double> hints_;
  double next_plan_time_ = 0;  // the next sample is taken at or after this plan time
};

}  // namespace xmate::teach
