// SPDX-License-Identifier: Apache-2.0
// Demonstrated paths (PATH instructions, docs/teach.md "Teach by demonstration"): joints at a fixed
// rate, the C2 cubic spline through them that a replay follows, the recorder that takes every
// sample of the real-time stream while the operator guides the arm, and the reduction that stores a
// 1 kHz recording at the lowest rate that stays within kPathTolerance of it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "arm/arm.h"
#include "model/robot_spec.h"

namespace xmate::teach {

using JointPoint = std::array<double, 7>;  // rad; element 6 is 0 on 6-axis models

// A path as stored: q[k] at time k / rate_hz (s). Plain data.
struct JointPath {
  double rate_hz = 100;
  std::vector<JointPoint> q;
  double duration() const { return q.size() < 2 ? 0.0 : double(q.size() - 1) / rate_hz; }
};

// The largest |a[j] - b[j]| over the model's `dof` joints (rad). Real-time safe.
double largestJointChange(const JointPoint& a, const JointPoint& b, int dof);

// The joints at time t (s; clamped to the samples) of samples taken every `step` seconds, linearly
// between the two around it. Real-time safe.
JointPoint samplesAt(const std::vector<JointPoint>& q, double step, double t);

// What the program file allows (program_io.cpp checks it).
inline constexpr double kMinPathRate = 1;      // Hz
inline constexpr double kMaxPathRate = 1000;   // Hz
inline constexpr size_t kMinPathSamples = 2;
// The reduction keeps every joint of the spline through the stored samples within this of every
// recorded sample; stored values are rounded to kPathResolution (the rounding counts against it).
inline constexpr double kPathTolerance = 1e-4;   // rad (0.1 mrad)
inline constexpr double kPathResolution = 1e-6;  // rad
// The rates a reduction tries, lowest first: each divides 1 kHz, so a 1 kHz recording is a subset.
inline constexpr std::array<double, 6> kPathRates{100, 125, 200, 250, 500, 1000};

// The natural cubic spline through a path's samples (continuous velocity and acceleration, jerk
// piecewise constant): what a replay follows and what deviations are measured against. Building it
// allocates; evaluate() does not (real-time safe, any thread for a const spline).
class PathSpline {
 public:
  PathSpline() = default;
  // dof: the joints the model has (the rest stay 0). Throws std::invalid_argument for fewer than 2
  // samples or a rate that is not finite and > 0.
  PathSpline(const std::vector<JointPoint>& q, double rate_hz, int dof);
  explicit PathSpline(const JointPath& path, int dof) : PathSpline(path.q, path.rate_hz, dof) {}

  double duration() const { return duration_; }
  int dof() const { return dof_; }
  bool empty() const { return q_.empty(); }
  // Joints and their first three derivatives with respect to path time at t (clamped to
  // [0, duration]); pass nullptr for what is not wanted.
  void evaluate(double t, JointPoint& q, JointPoint* dq = nullptr, JointPoint* ddq = nullptr,
                JointPoint* dddq = nullptr) const;
  JointPoint at(double t) const {
    JointPoint q{};
    evaluate(t, q);
    return q;
  }

 private:
  std::vector<JointPoint> q_;  // the samples
  std::vector<JointPoint> m_;  // second derivatives at the samples
  double h_ = 0;               // s between samples
  double duration_ = 0;
  int dof_ = 0;
};

// The part of a recording where the arm moves: [first, last] (indices), without the stretches at
// either end where every joint is slower than `rest_speed` (rad/s). first > last when it never moved.
struct ActiveSpan {
  size_t first = 0, last = 0;
  bool moved() const { return first < last; }
};
inline constexpr double kRestSpeed = 5e-3;  // rad/s
ActiveSpan activeSpan(const std::vector<JointPoint>& q, double rate_hz, int dof, double rest_speed = kRestSpeed);

// A recording (q at rate_hz) stored at the lowest of kPathRates whose spline stays within
// `tolerance` of every recorded sample, values rounded to kPathResolution; 1000 Hz (or the
// recording's own rate, if higher) when none does. The last stored sample is the recording's last
// (the arm rests there), held for the part of an interval the new rate adds.
struct Reduction {
  JointPath path;
  double max_error = 0;  // rad: the largest |spline - recorded sample| over every sample and joint
};
Reduction reducePath(const std::vector<JointPoint>& q, double rate_hz, int dof, double tolerance = kPathTolerance);

// Records a demonstration from the arm's sample stream (arm::Arm::takeSamples, Session's
// armSamplesArrived): every cycle's measured joints, in order. Cycles missing from the stream (the
// ring overflowed) are counted and bridged by the spline; a new controller session ends the
// recording (the samples after it are ignored and sessionChanged() says so). One thread.
class PathRecorder {
 public:
  PathRecorder(const model::RobotSpec& spec, double cycle_s);
  void add(const arm::ArmSample& sample);
  void add(const arm::ArmSample* samples, size_t count) {
    for (size_t i = 0; i < count; ++i) add(samples[i]);
  }
  size_t samples() const { return q_.size(); }
  uint64_t lostCycles() const { return lost_; }
  bool sessionChanged() const { return session_changed_; }
  double seconds() const;                   // recorded so far
  const std::vector<JointPoint>& raw() const { return q_; }  // every cycle (lost ones bridged)

  // The recording as a path: rest trimmed at both ends, reduced (reducePath). Throws
  // std::runtime_error (operator words) when fewer than 2 samples came or the arm did not move.
  struct Result {
    JointPath path;
    double max_error = 0;          // of the reduction, rad
    size_t recorded = 0;           // samples taken (cycles, bridged ones included)
    double trimmed_start = 0;      // s of rest cut at the start
    double trimmed_end = 0;        // ... and at the end
    uint64_t lost_cycles = 0;
  };
  Result finish() const;

 private:
  const model::RobotSpec& spec_;
  double cycle_s_;
  std::vector<JointPoint> q_;
  bool started_ = false;
  bool session_changed_ = false;
  uint64_t last_cycle_ = 0;
  uint32_t session_ = 0;
  uint64_t lost_ = 0;
};

// What the Program panel's table shows of a path: its duration, the length of its TCP path (forward
// kinematics with `tool`, m, over every sample) and its sample count.
struct PathSummary {
  double duration = 0;     // s
  double tcp_length = 0;   // m
  size_t samples = 0;
};
PathSummary summarizePath(const JointPath& path, const model::RobotSpec& spec, const std::array<double, 16>& tool);
// The TCP positions along a path (m, base frame; forward kinematics with `tool`), at most max_points
// evenly spread over it, the first and last sample included: the 3D view's trace.
std::vector<std::array<double, 3>> tcpTrace(const JointPath& path, const model::RobotSpec& spec,
                                            const std::array<double, 16>& tool, size_t max_points = 2000);

}  // namespace xmate::teach
