// ChartCanvas (chart_canvas.h): the Qt Charts backend of PlotCanvas.
#include "plots/chart_canvas.h"

#include <QChart>

#include <algorithm>
#include <cmath>
#include <QChartView>
#include <QLineSeries>
#include <QPen>
#include <QValueAxis>

namespace rci::ui::plots {

namespace {

// A tick spacing of 1, 2 or 5 x 10^k giving about `ticks` intervals over span.
double niceStep(double span, int ticks) {
  const double raw = span / std::max(1, ticks);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double factor : {1.0, 2.0, 5.0})
    if (raw <= factor * magnitude) return factor * magnitude;
  return 10 * magnitude;
}

// Ticks on round values (multiples of a nice step, anchored at 0) with just enough decimals: as the
// time axis scrolls, the labels stay put on whole values instead of changing every frame.
void applyNiceTicks(QValueAxis* axis, double span, int ticks) {
  if (!(span > 0) || !std::isfinite(span)) return;
  const double step = niceStep(span, ticks);
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step))), 0, 6);
  const QString format = QStringLiteral("%.%1f").arg(decimals);
  if (axis->tickInterval() != step) axis->setTickInterval(step);
  if (axis->labelFormat() != format) axis->setLabelFormat(format);
}

}  // namespace

ChartCanvas::ChartCanvas(QWidget* parent) {
  chart_ = new QChart;
  chart_->legend()->hide();  // the joint and signal choosers carry the colours and styles
  chart_->setMargins(QMargins(4, 4, 4, 4));
  chart_->setBackgroundRoundness(0);
  chart_->setAnimationOptions(QChart::NoAnimation);
  x_axis_ = new QValueAxis;
  y_axis_ = new QValueAxis;
  for (QValueAxis* axis : {x_axis_, y_axis_}) {
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0);
    axis->setTickInterval(1);
  }
  chart_->addAxis(x_axis_, Qt::AlignBottom);
  chart_->addAxis(y_axis_, Qt::AlignLeft);
  view_ = new QChartView(chart_, parent);  // takes ownership of the chart
  view_->setRenderHint(QPainter::Antialiasing, false);
  view_->setMinimumHeight(140);
}

ChartCanvas::~ChartCanvas() = default;  // the view (and chart) belong to the widget tree

QWidget* ChartCanvas::widget() { return view_; }

void ChartCanvas::setAxisTitles(const QString& x_title, const QString& y_title) {
  x_axis_->setTitleText(x_title);
  y_axis_->setTitleText(y_title);
}

void ChartCanvas::addSeries(int id, const QString& name, const QColor& colour, Qt::PenStyle style) {
  if (series_.contains(id)) return;
  auto* series = new QLineSeries;
  series->setName(name);
  series->setUseOpenGL(false);  // software rendering: works on every platform, offscreen included
  QPen pen(colour);
  pen.setWidthF(1.2);
  pen.setStyle(style);
  pen.setCosmetic(true);
  series->setPen(pen);
  chart_->addSeries(series);
  series->attachAxis(x_axis_);
  series->attachAxis(y_axis_);
  series_.insert(id, series);
}

void ChartCanvas::setSeries(int id, const QList<QPointF>& points) {
  if (QLineSeries* series = series_.value(id)) series->replace(points);
}

void ChartCanvas::setSeriesVisible(int id, bool visible) {
  QLineSeries* series = series_.value(id);
  if (series == nullptr || series->isVisible() == visible) return;
  series->setVisible(visible);
  if (!visible) series->clear();
}

void ChartCanvas::setXRange(double min, double max) {
  if (x_axis_->min() == min && x_axis_->max() == max) return;
  x_axis_->setRange(min, max);
  applyNiceTicks(x_axis_, max - min, 6);
}

void ChartCanvas::setYRange(double min, double max) {
  if (y_axis_->min() == min && y_axis_->max() == max) return;
  y_axis_->setRange(min, max);
  applyNiceTicks(y_axis_, max - min, 4);
}

int ChartCanvas::plotWidth() const {
  const int width = static_cast<int>(chart_->plotArea().width());
  return width > 10 ? width : std::max(10, view_->width());
}

int ChartCanvas::plotHeight() const {
  const int height = static_cast<int>(chart_->plotArea().height());
  return height > 10 ? height : std::max(10, view_->height());
}

bool ChartCanvas::isSeriesVisible(int id) const {
  const QLineSeries* series = series_.value(id);
  return series != nullptr && series->isVisible();
}

QList<QPointF> ChartCanvas::seriesPoints(int id) const {
  const QLineSeries* series = series_.value(id);
  return series != nullptr ? series->points() : QList<QPointF>{};
}

int ChartCanvas::visibleSeriesCount() const {
  int count = 0;
  for (const QLineSeries* series : series_) count += series->isVisible() ? 1 : 0;
  return count;
}

}  // namespace rci::ui::plots
