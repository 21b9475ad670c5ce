// SPDX-License-Identifier: Apache-2.0
// ChartCanvas: PlotCanvas on Qt Charts -- the chart's axes, grid and titles, with the curves drawn
// by a TraceLayer inside it (one polyline per series per frame, software rendering), value axes set
// by the caller, and a plot area with a fixed left margin so that stacked charts line up.
#pragma once

#include "plots/plot_canvas.h"

class QChart;
class QChartView;
class QValueAxis;

namespace rci::ui::plots {

class ChartCanvas : public PlotCanvas {
 public:
  explicit ChartCanvas(QWidget* parent = nullptr);
  ~ChartCanvas() override;

  QWidget* widget() override;
  void setAxisTitles(const QString& x_title, const QString& y_title) override;
  void addSeries(int id, const QString& name, const QColor& colour, Qt::PenStyle style) override;
  void setSeries(int id, const QList<QPointF>& points) override;
  void setSeriesVisible(int id, bool visible) override;
  void setXRange(double min, double max) override;
  void setYRange(double min, double max) override;
  int plotWidth() const override;
  int plotHeight() const override;
  bool isSeriesVisible(int id) const override;
  QList<QPointF> seriesPoints(int id) const override;
  int visibleSeriesCount() const override;

  // Shows or hides the time-axis tick labels (stacked charts label only the bottom one).
  void setXLabelsVisible(bool visible);
  // Places the plot area inside the view: a fixed left margin wide enough for any value label,
  // bottom room for the time labels and title when shown. Called on every resize of the view.
  void layoutPlotArea();

 private:
  QChart* chart_ = nullptr;
  QChartView* view_ = nullptr;
  QValueAxis* x_axis_ = nullptr;
  QValueAxis* y_axis_ = nullptr;
  class TraceLayer* traces_ = nullptr;  // owned by the chart
};

}  // namespace rci::ui::plots
