// SPDX-License-Identifier: Apache-2.0
// TraceLayer: the curves of one chart, drawn as plain QPainter polylines on an item inside the Qt
// Charts scene. The chart keeps its axes, grid, titles and plot area; only the lines bypass
// QLineSeries, whose every replace() strokes the whole line into a hit-test shape (1-2 us per point),
// which noisy 1 kHz torques cannot afford (docs/performance.md, "Live plots").
#pragma once

#include <QGraphicsItem>
#include <QHash>
#include <QList>
#include <QPen>
#include <QPointF>
#include <QPolygonF>

class QChart;

namespace rci::ui::plots {

class TraceLayer : public QGraphicsItem {
 public:
  // Becomes a child item of `chart`, drawn above its grid and clipped to its plot area.
  explicit TraceLayer(QChart* chart);

  // Declares trace `id` (once) with its pen; a trace starts visible and empty.
  void addTrace(int id, const QPen& pen);
  // Replaces the points of trace `id`, in axis units; x should increase.
  void setPoints(int id, const QList<QPointF>& points);
  // A hidden trace keeps no points.
  void setTraceVisible(int id, bool visible);
  // The axis ranges the points are mapped with (the chart's axes show the same).
  void setRanges(double x_min, double x_max, double y_min, double y_max);
  // Call when the chart's plot area moved or changed size.
  void plotAreaChanged();

  bool contains(int id) const { return traces_.contains(id); }
  bool isTraceVisible(int id) const;
  QList<QPointF> points(int id) const;
  int visibleCount() const;

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

 private:
  struct Trace {
    QPen pen;
    bool visible = true;
    QList<QPointF> points;
  };
  // Appends the pixel positions of points[first, last) to pixels_; returns where a non-finite value
  // ended the run (or last).
  qsizetype mapRun(const QList<QPointF>& points, qsizetype first, qsizetype last);

  QChart* chart_;
  QRectF area_;
  double x_min_ = 0, x_max_ = 1, y_min_ = 0, y_max_ = 1;
  QList<int> order_;  // drawing order: declaration order
  QHash<int, Trace> traces_;
  QPolygonF pixels_;  // reused by every paint
};

}  // namespace rci::ui::plots
