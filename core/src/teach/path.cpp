// SPDX-License-Identifier: Apache-2.0
// Demonstrated paths (path.h): the natural cubic spline through equally spaced samples (second
// derivatives from the tridiagonal system, solved once), trimming rest at the ends of a recording,
// the reduction to the lowest stored rate within the tolerance, and the recorder.
#include "teach/path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "model/arm_kinematics.h"

namespace xmate::teach {
namespace {

double roundTo(double v, double resolution) { return std::round(v / resolution) * resolution; }

std::string secondsText(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

}  // namespace

double largestJointChange(const JointPoint& a, const JointPoint& b, int dof) {
  double m = 0;
  for (int j = 0; j < dof; ++j) m = std::max(m, std::abs(a[size_t(j)] - b[size_t(j)]));
  return m;
}

JointPoint samplesAt(const std::vector<JointPoint>& q, double step, double t) {
  if (q.empty()) return {};
  const double x = std::clamp(std::isfinite(t) ? t / step : 0.0, 0.0, double(q.size() - 1));
  const size_t i = std::min(size_t(x), q.size() - 1);
  const size_t j = std::min(i + 1, q.size() - 1);
  const double f = x - double(i);
  JointPoint out{};
  for (size_t d = 0; d < 7; ++d) out[d] = q[i][d] + f * (q[j][d] - q[i][d]);
  return out;
}

// ---- PathSpline -------------------------------------------------------------------------------

PathSpline::PathSpline(const std::vector<JointPoint>& q, double rate_hz, int dof)
    : q_(q), m_(q.size(), JointPoint{}), dof_(std::clamp(dof, 0, 7)) {
  if (q.size() < 2) throw std::invalid_argument("PathSpline: a path needs at least 2 samples");
  if (!(std::isfinite(rate_hz) && rate_hz > 0)) throw std::invalid_argument("PathSpline: the rate must be finite and > 0");
  h_ = 1.0 / rate_hz;
  const size_t n = q.size() - 1;  // intervals
  duration_ = double(n) * h_;
  if (n < 2) return;  // a straight line: every second derivative 0
  // Natural spline, equal spacing: m[i-1] + 4 m[i] + m[i+1] = 6 (q[i+1] - 2 q[i] + q[i-1]) / h^2 for
  // i = 1..n-1, m[0] = m[n] = 0. Thomas algorithm: the same elimination factors for every joint.
  std::vector<double> c(n + 1, 0.0);  // the modified super-diagonal
  const double k = 6.0 / (h_ * h_);
  for (size_t i = 1; i < n; ++i) {
    const double denominator = 4.0 - (i > 1 ? c[i - 1] : 0.0);
    c[i] = 1.0 / denominator;
    for (int j = 0; j < dof_; ++j) {
      const double rhs = k * (q[i + 1][size_t(j)] - 2 * q[i][size_t(j)] + q[i - 1][size_t(j)]);
      m_[i][size_t(j)] = (rhs - (i > 1 ? m_[i - 1][size_t(j)] : 0.0)) / denominator;
    }
  }
  for (size_t i = n - 1; i >= 1; --i) {
    for (int j = 0; j < dof_; ++j) m_[i][size_t(j)] -= c[i] * m_[i + 1][size_t(j)];
    if (i == 1) break;
  }
}

void PathSpline::evaluate(double t, JointPoint& q, JointPoint* dq, JointPoint* ddq, JointPoint* dddq) const {
  q = JointPoint{};
  if (dq) *dq = JointPoint{};
  if (ddq) *ddq = JointPoint{};
  if (dddq) *dddq = JointPoint{};
  if (q_.empty()) return;
  const size_t n = q_.size() - 1;
  t = std::isfinite(t) ? std::clamp(t, 0.0, duration_) : 0.0;
  const size_t i = std::min(size_t(t / h_), n - 1);
  const double b = t - double(i) * h_;  // from sample i
  const double a = h_ - b;              // to sample i + 1
  const JointPoint &y0 = q_[i], &y1 = q_[i + 1], &m0 = m_[i], &m1 = m_[i + 1];
  for (int j = 0; j < dof_; ++j) {
    const size_t d = size_t(j);
    const double c0 = y0[d] / h_ - m0[d] * h_ / 6, c1 = y1[d] / h_ - m1[d] * h_ / 6;
    q[d] = (m0[d] * a * a * a + m1[d] * b * b * b) / (6 * h_) + c0 * a + c1 * b;
    if (dq) (*dq)[d] = (m1[d] * b * b - m0[d] * a * a) / (2 * h_) - c0 + c1;
    if (ddq) (*ddq)[d] = (m0[d] * a + m1[d] * b) / h_;
    if (dddq) (*dddq)[d] = (m1[d] - m0[d]) / h_;
  }
}

// ---- Trimming and reduction ----------------------------------------------------------------------

ActiveSpan activeSpan(const std::vector<JointPoint>& q, double rate_hz, int dof, double rest_speed) {
  ActiveSpan span{1, 0};
  if (q.size() < 2 || !(rate_hz > 0)) return span;
  // Speed by a central difference over +-10 ms, so that encoder noise does not count as motion.
  const size_t k = std::max<size_t>(1, size_t(std::lround(0.01 * rate_hz)));
  auto moving = [&](size_t i) {
    const size_t lo = i >= k ? i - k : 0, hi = std::min(q.size() - 1, i + k);
    const double dt = double(hi - lo) / rate_hz;
    for (int j = 0; j < dof; ++j)
      if (std::abs(q[hi][size_t(j)] - q[lo][size_t(j)]) / dt >= rest_speed) return true;
    return false;
  };
  size_t first = 0;
  while (first < q.size() && !moving(first)) ++first;
  if (first == q.size()) return span;
  size_t last = q.size() - 1;
  while (last > first && !moving(last)) --last;
  // Keep the window the speed was measured over: the path begins and ends where the arm still rests.
  span.first = first >= k ? first - k : 0;
  span.last = std::min(q.size() - 1, last + k);
  return span;
}

Reduction reducePath(const std::vector<JointPoint>& q, double rate_hz, int dof, double tolerance) {
  if (q.size() < 2) throw std::invalid_argument("reducePath: a recording needs at least 2 samples");
  const PathSpline recorded(q, rate_hz, dof);
  const double duration = recorded.duration();
  // The candidates up to the recording's own rate (no point storing more samples than were taken);
  // the lowest one always, so that a slower recording (RSI every 12 ms) is stored at 100 Hz.
  std::vector<double> rates;
  for (double rate : kPathRates)
    if (rate <= rate_hz * (1 + 1e-9) || rates.empty()) rates.push_back(rate);
  Reduction candidate;
  for (size_t r = 0; r < rates.size(); ++r) {
    const bool last_chance = r + 1 == rates.size();
    candidate = Reduction{};
    candidate.path.rate_hz = rates[r];
    const size_t count = std::max<size_t>(2, size_t(std::ceil(duration * rates[r] - 1e-6)) + 1);
    candidate.path.q.resize(count);
    for (size_t m = 0; m < count; ++m) {
      JointPoint& p = candidate.path.q[m];
      p = recorded.at(std::min(duration, double(m) / rates[r]));  // the last one holds the final rest
      for (int j = 0; j < dof; ++j) p[size_t(j)] = roundTo(p[size_t(j)], kPathResolution);
    }
    const PathSpline stored(candidate.path, dof);
    for (size_t k = 0; k < q.size(); ++k) {
      const JointPoint p = stored.at(double(k) / rate_hz);
      for (int j = 0; j < dof; ++j)
        candidate.max_error = std::max(candidate.max_error, std::abs(p[size_t(j)] - q[k][size_t(j)]));
      if (candidate.max_error > tolerance && !last_chance) break;
    }
    if (candidate.max_error <= tolerance) break;
  }
  return candidate;  // within the tolerance, or the highest rate tried
}

// ---- PathRecorder ----------------------------------------------------------------------------------

PathRecorder::PathRecorder(const model::RobotSpec& spec, double cycle_s) : spec_(spec), cycle_s_(cycle_s) {
  if (!(cycle_s > 0)) throw std::invalid_argument("PathRecorder: the cycle must be > 0");
  q_.reserve(size_t(120.0 / cycle_s));  // two minutes without reallocating
}

void PathRecorder::add(const arm::ArmSample& s) {
  if (!started_) {
    started_ = true;
    session_ = s.session;
    last_cycle_ = s.cycle;
    q_.push_back(s.q);
    return;
  }
  if (s.session != session_) {
    session_changed_ = true;
    return;
  }
  if (session_changed_ || s.cycle <= last_cycle_) return;
  const uint64_t gap = s.cycle - last_cycle_ - 1;
  lost_ += gap;
  // Bridge lost cycles linearly (at most 1 s of them; a longer silence restarts the controller's session).
  const JointPoint before = q_.back();
  const uint64_t bridged = std::min<uint64_t>(gap, uint64_t(1.0 / cycle_s_));
  for (uint64_t g = 1; g <= bridged; ++g) {
    const double f = double(g) / double(bridged + 1);
    JointPoint p{};
    for (size_t j = 0; j < 7; ++j) p[j] = before[j] + f * (s.q[j] - before[j]);
    q_.push_back(p);
  }
  q_.push_back(s.q);
  last_cycle_ = s.cycle;
}

double PathRecorder::seconds() const { return q_.size() < 2 ? 0.0 : double(q_.size() - 1) * cycle_s_; }

PathRecorder::Result PathRecorder::finish() const {
  if (q_.size() < 2)
    throw std::runtime_error("nothing was recorded (fewer than two controller cycles): start the recording, guide the "
                             "arm along the path, then stop it");
  const double rate = 1.0 / cycle_s_;
  const ActiveSpan span = activeSpan(q_, rate, spec_.dof);
  if (!span.moved())
    throw std::runtime_error("the arm did not move during the " + secondsText(seconds()) +
                             " recorded: guide it along the path between starting and stopping the recording");
  const std::vector<JointPoint> active(q_.begin() + long(span.first), q_.begin() + long(span.last) + 1);
  Reduction reduced = reducePath(active, rate, spec_.dof);
  Result r;
  r.path = std::move(reduced.path);
  r.max_error = reduced.max_error;
  r.recorded = q_.size();
  r.trimmed_start = double(span.first) * cycle_s_;
  r.trimmed_end = double(q_.size() - 1 - span.last) * cycle_s_;
  r.lost_cycles = lost_;
  return r;
}

// ---- Summaries ---------------------------------------------------------------------------------------

namespace {

model::ArmKinematics toolModel(const model::RobotSpec& spec, const std::array<double, 16>& tool) {
  model::ArmKinematics model(spec);
  model.SetCoor(tool);
  return model;
}

std::array<double, 3> tcpAt(const model::ArmKinematics& model, const JointPoint& q) {
  const std::array<double, 16> pose = model.GetCartPose(q);
  return {pose[3], pose[7], pose[11]};
}

}  // namespace

PathSummary summarizePath(const JointPath& path, const model::RobotSpec& spec, const std::array<double, 16>& tool) {
  PathSummary s;
  s.samples = path.q.size();
  s.duration = path.duration();
  if (path.q.empty()) return s;
  const model::ArmKinematics model = toolModel(spec, tool);
  std::array<double, 3> previous = tcpAt(model, path.q.front());
  for (size_t k = 1; k < path.q.size(); ++k) {
    const std::array<double, 3> p = tcpAt(model, path.q[k]);
    s.tcp_length += std::hypot(p[0] - previous[0], p[1] - previous[1], p[2] - previous[2]);
    previous = p;
  }
  return s;
}

std::vector<std::array<double, 3>> tcpTrace(const JointPath& path, const model::RobotSpec& spec,
                                            const std::array<double, 16>& tool, size_t max_points) {
  std::vector<std::array<double, 3>> trace;
  if (path.q.empty()) return trace;
  const model::ArmKinematics model = toolModel(spec, tool);
  const size_t n = path.q.size();
  const size_t points = std::clamp<size_t>(max_points, 2, std::max<size_t>(n, 2));
  if (n <= points) {
    for (const JointPoint& q : path.q) trace.push_back(tcpAt(model, q));
    return trace;
  }
  for (size_t k = 0; k < points; ++k) trace.push_back(tcpAt(model, path.q[k * (n - 1) / (points - 1)]));
  return trace;
}

}  // namespace xmate::teach
