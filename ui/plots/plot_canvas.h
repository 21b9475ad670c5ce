// SPDX-License-Identifier: Apache-2.0
// PlotCanvas: the small drawing interface the plots are written against, so the Qt Charts backend
// (deprecated from Qt 6.10) can be swapped for Qt Graphs without touching the data path.
#pragma once

#include <QColor>
#include <QList>
#include <QPointF>
#include <QString>

class QWidget;

namespace rci::ui::plots {

class PlotCanvas {
 public:
  virtual ~PlotCanvas() = default;

  virtual QWidget* widget() = 0;
  // Axis titles with units, e.g. "Time (s)", "Position (rad)".
  virtual void setAxisTitles(const QString& x_title, const QString& y_title) = 0;
  // Declares series id (once), drawn in colour with pen style (solid, dashed, dotted).
  virtual void addSeries(int id, const QString& name, const QColor& colour, Qt::PenStyle style) = 0;
  // Replaces all points of series id in one go (one call per series per frame).
  virtual void setSeries(int id, const QList<QPointF>& points) = 0;
  virtual void setSeriesVisible(int id, bool visible) = 0;
  virtual void setXRange(double min, double max) = 0;
  virtual void setYRange(double min, double max) = 0;
  // Width of the plot area in device-independent pixels: the number of decimation columns.
  virtual int plotWidth() const = 0;
  // Height of the plot area in pixels: how many y units one pixel is.
  virtual int plotHeight() const = 0;

  // Inspection (tests, export of the view).
  virtual bool isSeriesVisible(int id) const = 0;
  virtual QList<QPointF> seriesPoints(int id) const = 0;
  virtual int visibleSeriesCount() const = 0;
};

}  // namespace rci::ui::plots
