// SPDX-License-Identifier: Apache-2.0
// MinMaxDecimator (decimation.h): per-column extremes of a time series, in one pass.
#include "plots/decimation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rci::ui::plots {

void MinMaxDecimator::begin(double x0, double x1, int columns, QList<QPointF>& out) {
  out_ = &out;
  out_->clear();
  columns_ = std::max(1, columns);
  x0_ = x0;
  scale_ = x1 > x0 ? columns_ / (x1 - x0) : 0.0;
  column_ = -1;
  any_ = false;
  x1_ = x1;
}

void MinMaxDecimator::add(const double* time, const double* value, int count) {
  for (int i = 0; i < count; ++i) {
    const double t = time[i], v = value[i];
    if (t < x0_ || t > x1_ || !std::isfinite(v)) continue;
    take(t, v);
  }
}

void MinMaxDecimator::take(double t, double v) {
  const int column = std::min(columns_ - 1, static_cast<int>((t - x0_) * scale_));
  if (!any_) {
    any_ = true;
    keep(t, v);  // the first sample is always kept
  }
  if (column != column_) {
    flushColumn();
    column_ = column;
    min_ = max_ = {t, v};
  } else if (v < min_.v) {
    min_ = {t, v};
  } else if (v > max_.v) {
    max_ = {t, v};
  }
  last_ = {t, v};
}

void MinMaxDecimator::flushColumn() {
  if (column_ < 0) return;
  const Extreme& early = min_.t <= max_.t ? min_ : max_;
  const Extreme& late = min_.t <= max_.t ? max_ : min_;
  keep(early.t, early.v);
  keep(late.t, late.v);
}

void MinMaxDecimator::keep(double t, double v) {
  if (!out_->isEmpty() && out_->constLast().x() == t) return;  // the same sample twice
  out_->append(QPointF(t, v));
}

void MinMaxDecimator::finish() {
  if (!any_) return;
  flushColumn();
  column_ = -1;
  keep(last_.t, last_.v);  // the last sample is always kept
}

// The "sleeve" method, one pass: from the last kept point (the anchor), the slopes that pass within
// tolerance of every point seen since form an interval; the first point whose own slope leaves it ends
// the stretch, and the point before it becomes the next anchor.
void simplifyWithin(QList<QPointF>& points, double tolerance) {
  const qsizetype n = points.size();
  if (n <= 2 || !(tolerance > 0)) return;
  QPointF* p = points.data();
  qsizetype kept = 0;  // p[0..kept] are the output so far; p[kept] is the anchor
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  for (qsizetype i = 1; i < n; ++i) {
    double dx = p[i].x() - p[kept].x();
    const double slope = (p[i].y() - p[kept].y()) / dx;
    if (slope < lo || slope > hi) {
      p[++kept] = p[i - 1];  // the stretch ends at the previous point
      lo = -std::numeric_limits<double>::infinity();
      hi = std::numeric_limits<double>::infinity();
      dx = p[i].x() - p[kept].x();
    }
    lo = std::max(lo, (p[i].y() - tolerance - p[kept].y()) / dx);
    hi = std::min(hi, (p[i].y() + tolerance - p[kept].y()) / dx);
  }
  p[++kept] = p[n - 1];
  points.resize(kept + 1);
}

void decimateMinMax(const double* time, const double* value, int count, double x0, double x1, int columns,
                    QList<QPointF>& out) {
  MinMaxDecimator decimator;
  decimator.begin(x0, x1, columns, out);
  decimator.add(time, value, count);
  decimator.finish();
}

}  // namespace rci::ui::plots
