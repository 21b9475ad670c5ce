// SPDX-License-Identifier: Apache-2.0
// Min/max-per-pixel-column decimation (docs/architecture.md, "Live plots at 1 kHz") and the half-pixel line
// simplification that follows it: a single-sample spike survives at any zoom.
#pragma once

#include <QList>
#include <QPointF>

namespace rci::ui::plots {

// Reduces a series of any length to at most two points per pixel column (its lowest and highest
// sample, in time order) plus its first and last sample, so no peak is skipped.
// Streaming form: begin(), add() runs of samples in time order, finish(). Samples outside [x0, x1]
// and non-finite values are skipped. Output x increases strictly; every point is an input sample.
class MinMaxDecimator {
 public:
  void begin(double x0, double x1, int columns, QList<QPointF>& out);
  void add(const double* time, const double* value, int count);
  void finish();

 private:
  struct Extreme {
    double t = 0, v = 0;
  };
  void take(double t, double v);
  void flushColumn();
  void keep(double t, double v);

  QList<QPointF>* out_ = nullptr;
  double x0_ = 0, x1_ = 0, scale_ = 0;
  int columns_ = 1;
  int column_ = -1;        // column being collected; -1 before the first sample
  Extreme min_, max_, last_;
  bool any_ = false;
};

// Second stage, in place: drops points that lie within tolerance (vertically, in y units) of the line
// that joins the points kept around them, so every input point stays within tolerance of the drawn
// line. Keeps the first and last point and every peak standing more than 2 x tolerance out; x must
// increase strictly (as decimateMinMax delivers). With tolerance = half a pixel the line looks the same
// while smooth stretches shrink to a few points -- the cost of a redraw grows with points.
void simplifyWithin(QList<QPointF>& points, double tolerance);

// The whole reduction of one contiguous series; out is cleared first.
void decimateMinMax(const double* time, const double* value, int count, double x0, double x1, int columns,
                    QList<QPointF>& out);

}  // namespace rci::ui::plots
