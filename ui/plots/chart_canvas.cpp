// SPDX-License-Identifier: Apache-2.0
// ChartCanvas (chart_canvas.h): the Qt Charts backend of PlotCanvas.
#include "plots/chart_canvas.h"

#include "plots/trace_layer.h"

#include <QChart>
#include <QChartView>
#include <QFontMetrics>
#include <QGraphicsLayout>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace rci::ui::plots {

namespace {

// The smallest tick spacing of 1, 2 or 5 x 10^k that puts at most max_labels ticks on a span.
double niceStep(double span, int max_labels) {
  double magnitude = std::pow(10.0, std::floor(std::log10(span / std::max(1, max_labels))));
  for (int decade = 0; decade < 4; ++decade, magnitude *= 10)
    for (double factor : {1.0, 2.0, 5.0})
      if (std::floor(span / (factor * magnitude)) + 1 <= max_labels) return factor * magnitude;
  return magnitude;
}

// Ticks on round values (multiples of a nice step, anchored at 0) with just enough decimals: as the
// time axis scrolls, the labels stay put on whole values instead of changing every frame.
void applyNiceTicks(QValueAxis* axis, double span, int max_labels) {
  if (!(span > 0) || !std::isfinite(span)) return;
  const double step = niceStep(span, max_labels);
  const int decimals = std::clamp(static_cast<int>(-std::floor(std::log10(step))), 0, 6);
  const QString format = QStringLiteral("%.%1f").arg(decimals);
  if (axis->tickInterval() != step) axis->setTickInterval(step);
  if (axis->labelFormat() != format) axis->setLabelFormat(format);
}

constexpr int kTimeLabels = 7;  // at most this many time labels: every 2 s of a 10 s window

// The widest value label the axes are laid out for: wider ones are still drawn, just closer to the title.
const QString kWidestValueLabel = QStringLiteral("-0000.00");
constexpr int kGap = 4;             // pixels between title, labels and the plot area
constexpr int kMinPlotHeight = 50;  // the smallest plot area a chart shrinks to

// A chart view that re-places the plot area whenever it is resized.
class FixedAreaView : public QChartView {
 public:
  FixedAreaView(QChart* chart, QWidget* parent, std::function<void()> on_resize)
      : QChartView(chart, parent), on_resize_(std::move(on_resize)) {}

 protected:
  void resizeEvent(QResizeEvent* event) override {
    QChartView::resizeEvent(event);  // resizes the chart to the view first
    on_resize_();
  }

 private:
  std::function<void()> on_resize_;
};

// How many value labels fit the plot height: Qt Charts elides a label given less than its own
// height plus 5 px padding above and below (2 to 5 labels).
int valueLabelCount(double plot_height, const QFont& labels_font) {
  const int label_height = QFontMetrics(labels_font).height();
  return std::clamp(static_cast<int>(plot_height / (label_height + 12)), 2, 5);
}

QFont smallerFont(const QFont& font) {
  QFont smaller(font);
  if (smaller.pointSizeF() > 0) smaller.setPointSizeF(std::max(7.0, smaller.pointSizeF() - 1));
  return smaller;
}

}  // namespace

ChartCanvas::ChartCanvas(QWidget* parent) {
  chart_ = new QChart;
  chart_->legend()->hide();  // the joint and signal choosers carry the colours and styles
  chart_->setMargins(QMargins(0, 0, 0, 0));
  chart_->layout()->setContentsMargins(0, 0, 0, 0);
  chart_->setBackgroundRoundness(0);
  chart_->setAnimationOptions(QChart::NoAnimation);
  x_axis_ = new QValueAxis;
  y_axis_ = new QValueAxis;
  for (QValueAxis* axis : {x_axis_, y_axis_}) {
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0);
    axis->setTickInterval(1);
    axis->setLabelsFont(smallerFont(axis->labelsFont()));
    axis->setTitleFont(smallerFont(axis->titleFont()));
  }
  chart_->addAxis(x_axis_, Qt::AlignBottom);
  chart_->addAxis(y_axis_, Qt::AlignLeft);
  // The view takes ownership of the chart.
  view_ = new FixedAreaView(chart_, parent, [this] { layoutPlotArea(); });
  view_->setRenderHint(QPainter::Antialiasing, false);
  view_->setFrameShape(QFrame::NoFrame);
  traces_ = new TraceLayer(chart_);
  QObject::connect(chart_, &QChart::plotAreaChanged, chart_, [this] { traces_->plotAreaChanged(); });
}

ChartCanvas::~ChartCanvas() = default;  // the view (and chart) belong to the widget tree

QWidget* ChartCanvas::widget() { return view_; }

void ChartCanvas::setAxisTitles(const QString& x_title, const QString& y_title) {
  x_axis_->setTitleText(x_title);
  y_axis_->setTitleText(y_title);
  layoutPlotArea();
}

void ChartCanvas::setXLabelsVisible(bool visible) {
  x_axis_->setLabelsVisible(visible);
  layoutPlotArea();
}

void ChartCanvas::layoutPlotArea() {
  const QFontMetrics labels(y_axis_->labelsFont());
  const QFontMetrics titles(y_axis_->titleFont());
  const bool y_title = !y_axis_->titleText().isEmpty();
  const bool x_labels = x_axis_->labelsVisible();
  const bool x_title = !x_axis_->titleText().isEmpty();
  const int half_label = labels.height() / 2 + 1;  // the top and bottom value labels overhang the plot
  const int left = (y_title ? titles.height() + kGap : 0) + labels.horizontalAdvance(kWidestValueLabel) + 2 * kGap;
  const int right = labels.horizontalAdvance(QStringLiteral("-00")) / 2 + kGap;
  const int top = half_label + 1;
  const int bottom = (x_labels ? labels.height() + 2 * kGap : half_label + 1) + (x_title ? titles.height() + kGap : 0);
  view_->setMinimumHeight(top + bottom + kMinPlotHeight);
  const QSizeF size = chart_->size();
  const QRectF area(left, top, std::max(10.0, size.width() - left - right), std::max(10.0, size.height() - top - bottom));
  if (chart_->plotArea() != area) chart_->setPlotArea(area);
  applyNiceTicks(y_axis_, y_axis_->max() - y_axis_->min(), valueLabelCount(area.height(), y_axis_->labelsFont()));
}

void ChartCanvas::addSeries(int id, const QString&, const QColor& colour, Qt::PenStyle style) {
  QPen pen(colour);
  pen.setWidthF(1.0);
  pen.setStyle(style);
  pen.setCosmetic(true);
  traces_->addTrace(id, pen);
}

void ChartCanvas::setSeries(int id, const QList<QPointF>& points) { traces_->setPoints(id, points); }

void ChartCanvas::setSeriesVisible(int id, bool visible) { traces_->setTraceVisible(id, visible); }

void ChartCanvas::setXRange(double min, double max) {
  if (x_axis_->min() == min && x_axis_->max() == max) return;
  x_axis_->setRange(min, max);
  traces_->setRanges(min, max, y_axis_->min(), y_axis_->max());
  applyNiceTicks(x_axis_, max - min, kTimeLabels);
}

void ChartCanvas::setYRange(double min, double max) {
  if (y_axis_->min() == min && y_axis_->max() == max) return;
  y_axis_->setRange(min, max);
  traces_->setRanges(x_axis_->min(), x_axis_->max(), min, max);
  applyNiceTicks(y_axis_, max - min, valueLabelCount(chart_->plotArea().height(), y_axis_->labelsFont()));
}

int ChartCanvas::plotWidth() const {
  const int width = static_cast<int>(chart_->plotArea().width());
  return width > 10 ? width : std::max(10, view_->width());
}

int ChartCanvas::plotHeight() const {
  const int height = static_cast<int>(chart_->plotArea().height());
  return height > 10 ? height : std::max(10, view_->height());
}

bool ChartCanvas::isSeriesVisible(int id) const { return traces_->isTraceVisible(id); }

QList<QPointF> ChartCanvas::seriesPoints(int id) const { return traces_->points(id); }

int ChartCanvas::visibleSeriesCount() const { return traces_->visibleCount(); }

}  // namespace rci::ui::plots
