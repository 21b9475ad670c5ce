// SPDX-License-Identifier: Apache-2.0
// Re-timing a demonstrated path for replay (docs/teach.md, "Replaying a path"): the demonstrated
// timing scaled by the instruction's speed, slowed where that would exceed the joints' velocity,
// acceleration or jerk limits -- the geometry is kept, only the pace along it changes -- starting
// and ending at rest. And how far a replay strayed from the path. Any thread; allocates.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "model/arm_kinematics.h"
#include "model/robot_spec.h"
#include "teach/path.h"

namespace xmate::teach {

// The replay plan: joints every `step` seconds of replay time, from the path's first sample to its
// last, at rest at both ends. Its velocity, acceleration and jerk (finite differences at `step`)
// stay within kPathLimitShare of the model's rated limits.
struct PathTiming {
  double step = 1e-3;                 // s between two samples
  std::vector<JointPoint> q;          // rad
  std::vector<double> path_time;      // the demonstrated time (s, of the path) each sample replays
  double duration = 0;                // s: (q.size() - 1) * step
  double nominal_duration = 0;        // s: the path's duration / speed, as if never slowed
  // How much the limits slowed it: the lowest pace along the path relative to the asked speed (1:
  // never slowed; the ramps at both ends do not count), and the share of the path's time that was
  // replayed slower than asked.
  double slowest = 1;
  double slowed_share = 0;
  double slowest_at = 0;              // s of the path where the pace is lowest
};

// The share of the rated limits a replay plan may use; the rest is the reserve the executor's speed
// override, pause and stop ramp into (as kSpeedShare for the other motions).
inline constexpr double kPathLimitShare = 0.8;

// Plans the replay of `spline` at `speed` (0 < speed <= 1: 1 replays the demonstrated timing).
// Throws std::invalid_argument for a bad speed or step, std::runtime_error (saying where on the
// path, which joint and what to do) when no timing within the limits exists -- a path that would
// need more than kMaxPathSlowdown times its demonstrated duration at some point.
inline constexpr double kMaxPathSlowdown = 50.0;
PathTiming timePath(const PathSpline& spline, const model::RobotSpec& spec, double speed, double step = 1e-3);

// The joints of a timing at replay time t (clamped), linearly between samples. Real-time safe.
JointPoint timingAt(const PathTiming& timing, double t);

// How far measured joints strayed from the path: for each measured sample the nearest point of the
// spline within `window` seconds of path time around its hint (the path time the plan commanded
// then), max over joints (rad); and the TCP distance there (m, forward kinematics with `model`'s
// tool). A replay that lags along the path is not off the path.
struct PathDeviation {
  double joint = 0;     // rad
  double tcp = 0;       // m
  double at_time = 0;   // s of the path where the joint deviation is largest
};
PathDeviation pathDeviation(const PathSpline& spline, const model::ArmKinematics& model,
                            const std::vector<JointPoint>& measured, const std::vector<double>& hint_time,
                            double window = 0.2);

}  // namespace xmate::teach
