// SPDX-License-Identifier: Apache-2.0
// Re-timing a demonstrated path (path_timing.h). The replay moves along the path's spline S(t) at a
// pace sigma = dt/dtau (path time per replay time): velocity S' sigma, acceleration S'' sigma^2 +
// S' dsigma/dtau, jerk S''' sigma^3 + ... So, on a grid of path time:
//   1. a ceiling of the pace at every point: the asked speed, and what keeps S' sigma, S'' sigma^2
//      and S''' sigma^3 within kPathLimitShare of each joint's limits;
//   2. the ceiling smoothed (a sliding minimum, then two box averages inside it: never above it);
//   3. the pace itself, from 0 at the start to 0 at the end, its change |dsigma/dtau| bounded so
//      that S' dsigma/dtau stays a small share of the acceleration limits (forward and backward
//      passes on sigma^2, as in time-optimal path parameterisation);
//   4. replay time from the pace (constant dsigma/dtau within each grid interval), the path
//      sampled every `step` of it;
//   5. finite differences of those samples checked against the limits; where they exceed
//      kVerifyShare the ceiling is lowered there and the plan made again.
#include "teach/path_timing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <stdexcept>
#include <string>

namespace xmate::teach {
namespace {

constexpr double kGrid = 1e-3;             // s of path time between two points of the pace profile
constexpr double kSmoothing = 0.1;         // s of path time: the ceiling's smoothing half-width
constexpr double kPaceChangeShare = 0.05;  // of a joint's acceleration limit that dsigma/dtau may use
constexpr double kMaxPaceChange = 10.0;    // 1/s
constexpr double kMinPaceChange = 1e-3;    // 1/s
constexpr double kVerifyShare = 0.9;       // of the rated limits the samples must stay within
constexpr int kMaxRounds = 12;

const char* const kQuantity[3] = {"speed", "acceleration", "jerk"};
const char* const kUnit[3] = {"rad/s", "rad/s^2", "rad/s^3"};

// What limits the pace most at one point of the path.
struct Ceiling {
  double pace = 0;
  int joint = -1;     // -1: only the asked speed
  int quantity = 0;   // 0 velocity, 1 acceleration, 2 jerk
  double value = 0;   // the demonstrated derivative there
};

double limitOf(const model::RobotSpec& spec, int quantity, int joint) {
  const size_t j = size_t(joint);
  return quantity == 0 ? spec.dq_max[j] : quantity == 1 ? spec.ddq_max[j] : spec.jerk_max[j];
}

// Sliding minimum over +-w points (monotone deque), the window cut at the ends.
std::vector<double> windowMin(const std::vector<double>& x, size_t w) {
  std::vector<double> out(x.size());
  std::deque<size_t> window;  // indices with increasing values
  size_t next = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const size_t hi = std::min(x.size() - 1, i + w);
    for (; next <= hi; ++next) {
      while (!window.empty() && x[window.back()] >= x[next]) window.pop_back();
      window.push_back(next);
    }
    while (window.front() + w < i) window.pop_front();
    out[i] = x[window.front()];
  }
  return out;
}

// Average over +-w points, the window cut at the ends.
std::vector<double> boxAverage(const std::vector<double>& x, size_t w) {
  std::vector<double> sum(x.size() + 1, 0.0);
  for (size_t i = 0; i < x.size(); ++i) sum[i + 1] = sum[i] + x[i];
  std::vector<double> out(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const size_t lo = i >= w ? i - w : 0, hi = std::min(x.size() - 1, i + w);
    out[i] = (sum[hi + 1] - sum[lo]) / double(hi - lo + 1);
  }
  return out;
}

std::string describeCeiling(const Ceiling& c, double t) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "at t = %.2f s of the path, joint %d's demonstrated %s of %.3g %s", t, c.joint + 1,
                kQuantity[c.quantity], c.value, kUnit[c.quantity]);
  return buf;
}

class PathTimer {
 public:
  PathTimer(const PathSpline& spline, const model::RobotSpec& spec, double speed, double step)
      : spline_(spline), spec_(spec), speed_(speed), step_(step) {
    const double duration = spline.duration();
    n_ = std::max<size_t>(4, size_t(std::ceil(duration / kGrid)));
    h_ = duration / double(n_);
    width_ = std::max<size_t>(2, size_t(std::lround(kSmoothing / h_)));
    measurePath();
  }

  PathTiming run() {
    for (int round = 0; round < kMaxRounds; ++round) {
      PathTiming timing = plan();
      if (verify(timing)) return timing;
    }
    char buf[120];
    std::snprintf(buf, sizeof buf, "at t = %.2f s of the path,", worst_time_);
    throw std::runtime_error(std::string("the demonstrated path cannot be timed within the joint limits: ") + buf +
                             " joint " + std::to_string(worst_joint_ + 1) + "'s " + kQuantity[worst_quantity_] +
                             " stays too high however it is slowed; record that part again more smoothly");
  }

 private:
  const PathSpline& spline_;
  const model::RobotSpec& spec_;
  double speed_, step_;
  size_t n_ = 0;       // grid intervals
  double h_ = 0;       // s of path time between grid points
  size_t width_ = 2;   // smoothing half-width in grid points
  std::vector<double> ceiling_;      // of the pace, per grid point
  std::vector<double> pace_change_;  // the bound on |dsigma/dtau| per grid point, 1/s
  // The last verification's worst excess, for the error message.
  double worst_time_ = 0;
  int worst_joint_ = 0, worst_quantity_ = 0;

  double at(size_t i) const { return std::min(spline_.duration(), double(i) * h_); }

  // Steps 1 and the pace-change bound: from the spline's derivatives at every grid point.
  void measurePath() {
    ceiling_.assign(n_ + 1, speed_);
    pace_change_.assign(n_ + 1, kMaxPaceChange);
    Ceiling lowest{speed_};
    double lowest_time = 0;
    for (size_t i = 0; i <= n_; ++i) {
      JointPoint q, d[3];
      spline_.evaluate(at(i), q, &d[0], &d[1], &d[2]);
      Ceiling c{speed_};
      for (int j = 0; j < spec_.dof; ++j) {
        for (int k = 0; k < 3; ++k) {
          const double value = std::abs(d[k][size_t(j)]);
          if (!(value > 0)) continue;
          const double allowed = kPathLimitShare * limitOf(spec_, k, j) / value;
          const double pace = k == 0 ? allowed : k == 1 ? std::sqrt(allowed) : std::cbrt(allowed);
          if (pace < c.pace) c = {pace, j, k, d[k][size_t(j)]};
        }
        const double speed = std::abs(d[0][size_t(j)]);
        if (speed > 0)
          pace_change_[i] = std::min(pace_change_[i], kPaceChangeShare * spec_.ddq_max[size_t(j)] / speed);
      }
      pace_change_[i] = std::max(pace_change_[i], kMinPaceChange);
      ceiling_[i] = c.pace;
      if (c.pace < lowest.pace) {
        lowest = c;
        lowest_time = at(i);
      }
    }
    if (lowest.pace < speed_ / kMaxPathSlowdown) {
      char buf[120];
      std::snprintf(buf, sizeof buf, " (the joint allows %.3g %s): it would have to be replayed more than %.0f times ",
                    limitOf(spec_, lowest.quantity, lowest.joint), kUnit[lowest.quantity], kMaxPathSlowdown);
      throw std::runtime_error("the demonstrated path is too fast for the robot: " + describeCeiling(lowest, lowest_time) +
                               buf + "slower than demonstrated there; record it again more slowly");
    }
  }

  // Steps 2 to 4.
  PathTiming plan() const {
    const std::vector<double> envelope = boxAverage(boxAverage(windowMin(ceiling_, width_), width_ / 2), width_ / 2);
    PathTiming timing;
    timing.step = step_;
    timing.nominal_duration = spline_.duration() / speed_;
    size_t slowed = 0;
    for (size_t i = 0; i <= n_; ++i) {
      const double ratio = std::min(1.0, envelope[i] / speed_);
      if (ratio < 0.999) ++slowed;
      if (ratio < timing.slowest) {
        timing.slowest = ratio;
        timing.slowest_at = at(i);
      }
    }
    timing.slowed_share = double(slowed) / double(n_ + 1);

    // sigma^2 from 0 at both ends, d(sigma^2)/dt = 2 dsigma/dtau bounded.
    std::vector<double> u(n_ + 1);
    for (size_t i = 0; i <= n_; ++i) u[i] = envelope[i] * envelope[i];
    u[0] = 0;
    for (size_t i = 0; i < n_; ++i) u[i + 1] = std::min(u[i + 1], u[i] + 2 * pace_change_[i] * h_);
    u[n_] = 0;
    for (size_t i = n_; i-- > 0;) u[i] = std::min(u[i], u[i + 1] + 2 * pace_change_[i] * h_);
    std::vector<double> sigma(n_ + 1), tau(n_ + 1, 0.0);
    for (size_t i = 0; i <= n_; ++i) sigma[i] = std::sqrt(std::max(0.0, u[i]));
    for (size_t i = 0; i < n_; ++i) tau[i + 1] = tau[i] + 2 * h_ / (sigma[i] + sigma[i + 1]);

    // Replay samples: within a grid interval the pace changes linearly with replay time.
    const size_t count = size_t(std::ceil(tau[n_] / step_ - 1e-9)) + 1;
    timing.q.resize(count);
    timing.path_time.resize(count);
    size_t i = 0;
    for (size_t k = 0; k < count; ++k) {
      const double t_replay = double(k) * step_;
      double t = spline_.duration();
      if (t_replay < tau[n_]) {
        while (i + 1 < n_ && tau[i + 1] <= t_replay) ++i;
        const double dtau = tau[i + 1] - tau[i];
        const double s = t_replay - tau[i];
        const double a = (sigma[i + 1] - sigma[i]) / dtau;
        t = std::min(at(i + 1), at(i) + sigma[i] * s + 0.5 * a * s * s);
      }
      timing.path_time[k] = t;
      spline_.evaluate(t, timing.q[k]);
    }
    timing.duration = double(count - 1) * step_;
    return timing;
  }

  // Step 5: true when every finite difference is within the limits; else lowers the ceiling around
  // each excess for the next round.
  bool verify(const PathTiming& timing) {
    const std::vector<JointPoint>& q = timing.q;
    std::vector<double> factor(n_ + 1, 1.0);
    double worst = 1.0;
    bool ok = true;
    for (size_t k = 0; k + 1 < q.size(); ++k) {
      for (int j = 0; j < spec_.dof; ++j) {
        const size_t d = size_t(j);
        double value[3] = {(q[k + 1][d] - q[k][d]) / step_, 0, 0};
        if (k + 2 < q.size()) value[1] = (q[k + 2][d] - 2 * q[k + 1][d] + q[k][d]) / (step_ * step_);
        if (k + 3 < q.size())
          value[2] = (q[k + 3][d] - 3 * q[k + 2][d] + 3 * q[k + 1][d] - q[k][d]) / (step_ * step_ * step_);
        for (int m = 0; m < 3; ++m) {
          const double ratio = std::abs(value[m]) / (kVerifyShare * limitOf(spec_, m, j));
          if (ratio <= 1) continue;
          ok = false;
          const size_t at_grid = std::min(n_, size_t(std::lround(timing.path_time[k] / h_)));
          factor[at_grid] = std::min(factor[at_grid], 0.95 * std::pow(ratio, -1.0 / (m + 1)));
          if (ratio > worst) {
            worst = ratio;
            worst_time_ = timing.path_time[k];
            worst_joint_ = j;
            worst_quantity_ = m;
          }
        }
      }
    }
    if (ok) return true;
    const std::vector<double> spread = windowMin(factor, width_);
    for (size_t i = 0; i <= n_; ++i) ceiling_[i] *= spread[i];
    return false;
  }
};

}  // namespace

PathTiming timePath(const PathSpline& spline, const model::RobotSpec& spec, double speed, double step) {
  if (!(speed > 0 && speed <= 1)) throw std::invalid_argument("timePath: the speed must be in (0, 1]");
  if (!(step > 0 && step <= 0.1)) throw std::invalid_argument("timePath: the step must be in (0, 0.1] s");
  if (spline.empty()) throw std::invalid_argument("timePath: an empty path");
  return PathTimer(spline, spec, speed, step).run();
}

JointPoint timingAt(const PathTiming& timing, double t) { return samplesAt(timing.q, timing.step, t); }

namespace {

double squaredDistance(const JointPoint& a, const JointPoint& b, int dof) {
  double s = 0;
  for (int j = 0; j < dof; ++j) s += (a[size_t(j)] - b[size_t(j)]) * (a[size_t(j)] - b[size_t(j)]);
  return s;
}

// The path time in [lo, hi] nearest (joint space) to q, searched downhill from `start` in 1 ms
// steps, then narrowed to 1 us; `distance` gets the squared distance there.
double nearestTime(const PathSpline& spline, const JointPoint& q, double start, double lo, double hi,
                   double& distance) {
  const int dof = spline.dof();
  auto f = [&](double t) { return squaredDistance(q, spline.at(t), dof); };
  constexpr double kStep = 1e-3;
  double t = std::clamp(start, lo, hi), best = f(t);
  for (double direction : {1.0, -1.0}) {
    for (;;) {
      const double next = std::clamp(t + direction * kStep, lo, hi);
      const double value = f(next);
      if (next == t || !(value < best)) break;
      t = next;
      best = value;
    }
  }
  double a = std::max(lo, t - kStep), b = std::min(hi, t + kStep);
  while (b - a > 1e-6) {  // ternary search: the distance is smooth and unimodal this close
    const double m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
    if (f(m1) < f(m2)) b = m2;
    else a = m1;
  }
  distance = f(0.5 * (a + b));
  return 0.5 * (a + b);
}

}  // namespace

PathDeviation pathDeviation(const PathSpline& spline, const model::ArmKinematics& model,
                            const std::vector<JointPoint>& measured, const std::vector<double>& hint_time,
                            double window) {
  PathDeviation deviation;
  if (spline.empty()) return deviation;
  const size_t count = std::min(measured.size(), hint_time.size());
  const int dof = spline.dof();
  double lag = 0;  // where the previous sample was found, relative to its hint
  for (size_t k = 0; k < count; ++k) {
    const double hint = hint_time[k];
    const double lo = std::max(0.0, hint - window), hi = std::min(spline.duration(), hint + window);
    // From the hint, and from where the previous sample was found (a steady lag): the nearer. On a
    // stretch where the path rests the lag is arbitrary, so the hint alone would not do after it.
    double d_hint = 0, d_lag = 0;
    const double t_hint = nearestTime(spline, measured[k], hint, lo, hi, d_hint);
    const double t_lag = lag != 0 ? nearestTime(spline, measured[k], hint + lag, lo, hi, d_lag) : t_hint;
    const double t = lag != 0 && d_lag < d_hint ? t_lag : t_hint;
    lag = t - hint;
    const JointPoint p = spline.at(t);
    double joint = 0;
    for (int j = 0; j < dof; ++j) joint = std::max(joint, std::abs(measured[k][size_t(j)] - p[size_t(j)]));
    if (joint > deviation.joint) {
      deviation.joint = joint;
      deviation.at_time = t;
    }
    const std::array<double, 16> a = model.GetCartPose(measured[k]), b = model.GetCartPose(p);
    deviation.tcp = std::max(deviation.tcp, std::hypot(a[3] - b[3], a[7] - b[7], a[11] - b[11]));
  }
  return deviation;
}

}  // namespace xmate::teach
