// SPDX-License-Identifier: Apache-2.0
// TraceLayer (trace_layer.h): data -> pixel mapping and polyline drawing of a chart's curves.
#include "plots/trace_layer.h"

#include <QChart>
#include <QPainter>

#include <cmath>

namespace rci::ui::plots {

namespace {
// Above the chart's grid and series items (Qt Charts uses z values below 10 for its own items).
constexpr qreal kTraceZ = 20;
}  // namespace

TraceLayer::TraceLayer(QChart* chart) : QGraphicsItem(chart), chart_(chart) {
  setZValue(kTraceZ);
  setFlag(QGraphicsItem::ItemClipsToShape, false);
  setAcceptedMouseButtons(Qt::NoButton);
  plotAreaChanged();
}

void TraceLayer::addTrace(int id, const QPen& pen) {
  if (traces_.contains(id)) return;
  traces_.insert(id, Trace{pen, true, {}});
  order_.append(id);
}

void TraceLayer::setPoints(int id, const QList<QPointF>& points) {
  auto it = traces_.find(id);
  if (it == traces_.end() || !it->visible) return;
  it->points = points;
  update();
}

void TraceLayer::setTraceVisible(int id, bool visible) {
  auto it = traces_.find(id);
  if (it == traces_.end() || it->visible == visible) return;
  it->visible = visible;
  if (!visible) it->points.clear();
  update();
}

void TraceLayer::setRanges(double x_min, double x_max, double y_min, double y_max) {
  if (x_min == x_min_ && x_max == x_max_ && y_min == y_min_ && y_max == y_max_) return;
  x_min_ = x_min;
  x_max_ = x_max;
  y_min_ = y_min;
  y_max_ = y_max;
  update();
}

void TraceLayer::plotAreaChanged() {
  const QRectF area = chart_->plotArea();
  if (area == area_) return;
  prepareGeometryChange();
  area_ = area;
  update();
}

bool TraceLayer::isTraceVisible(int id) const {
  const auto it = traces_.find(id);
  return it != traces_.end() && it->visible;
}

QList<QPointF> TraceLayer::points(int id) const {
  const auto it = traces_.find(id);
  return it != traces_.end() ? it->points : QList<QPointF>{};
}

int TraceLayer::visibleCount() const {
  int count = 0;
  for (const Trace& trace : traces_) count += trace.visible ? 1 : 0;
  return count;
}

QRectF TraceLayer::boundingRect() const { return area_; }

qsizetype TraceLayer::mapRun(const QList<QPointF>& points, qsizetype first, qsizetype last) {
  const double sx = area_.width() / (x_max_ - x_min_), sy = area_.height() / (y_max_ - y_min_);
  const double left = area_.left(), bottom = area_.bottom();
  for (qsizetype i = first; i < last; ++i) {
    const QPointF& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return i;
    pixels_.append(QPointF(left + (p.x() - x_min_) * sx, bottom - (p.y() - y_min_) * sy));
  }
  return last;
}

void TraceLayer::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  if (!(x_max_ > x_min_) || !(y_max_ > y_min_) || area_.isEmpty()) return;
  painter->save();
  painter->setClipRect(area_);
  painter->setRenderHint(QPainter::Antialiasing, true);
  painter->setBrush(Qt::NoBrush);
  for (int id : std::as_const(order_)) {
    const Trace& trace = traces_.constFind(id).value();
    if (!trace.visible || trace.points.isEmpty()) continue;
    painter->setPen(trace.pen);
    // A non-finite sample breaks the line instead of drawing a spike to nowhere.
    for (qsizetype i = 0; i < trace.points.size();) {
      pixels_.clear();
      const qsizetype end = mapRun(trace.points, i, trace.points.size());
      if (pixels_.size() > 1) painter->drawPolyline(pixels_);
      i = end + 1;
    }
  }
  painter->restore();
}

}  // namespace rci::ui::plots
