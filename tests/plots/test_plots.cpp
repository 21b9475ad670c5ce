// SPDX-License-Identifier: Apache-2.0
// Tests of ui/plots: ring wrap-around and window queries, min/max decimation (spikes, bounds, order),
// CSV export (content, atomic replace), freeze, signal selection, and the J^T external-torque mapping.
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QPushButton>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <vector>

#include "plots/auto_scale.h"
#include "plots/chart_canvas.h"
#include "plots/csv_export.h"
#include "plots/decimation.h"
#include "plots/external_torque.h"
#include "plots/plot_buffer.h"
#include "plots/plots_widget.h"

using namespace rci::ui::plots;
using xmate::client::StateSample;

namespace {

ChannelValues filled(double v) {
  ChannelValues values;
  values.fill(v);
  return values;
}

// Every joint of every signal follows value; time t.
StateSample sampleAt(double t, double value) {
  StateSample s;
  s.time = t;
  s.q.fill(value);
  s.q_c.fill(value);
  s.dq_m.fill(value);
  s.tau_m.fill(value);
  s.tau_c.fill(value);
  return s;
}

std::vector<StateSample> ramp(double t0, int count) {
  std::vector<StateSample> samples;
  for (int i = 0; i < count; ++i) samples.push_back(sampleAt(t0 + i / 1000.0, std::sin(0.01 * i)));
  return samples;
}

QByteArray readAll(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void writeFile(const QString& path, const QByteArray& data) {
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly));
  file.write(data);
}

}  // namespace

class TestPlots : public QObject {
  Q_OBJECT
 private slots:
  void ringWrapsAround();
  void ringRefusesOlderSample();
  void windowQueryIsInclusive();
  void copyRangeKeepsSamples();
  void spikeSurvivesAnyZoom();
  void decimationStaysInBounds();
  void decimationAcrossSpansMatchesOneRun();
  void simplifyKeepsLineWithinTolerance();
  void autoScaleHasHysteresis();
  void csvHasHeaderWithUnitsAndRows();
  void csvReplacesFileOnlyOnSuccess();
  void freezeStopsUpdates();
  void signalSelectionChangesVisibleSeries();
  void chartsFitCompactDockAndLineUp();
  void tracesAreDrawnWhereTheAxesSay();
  void frozenViewExportHasShownSeries();
  void jointTorquesAreJTransposeF();
  void widgetMapsExternalWrench();
};

void TestPlots::ringWrapsAround() {
  PlotBuffer buffer(0.005, 1000);  // 5 samples
  QCOMPARE(buffer.capacity(), 5);
  for (int i = 0; i < 8; ++i) QVERIFY(buffer.push(i * 0.001, filled(i)));
  QCOMPARE(buffer.size(), 5);
  QCOMPARE(buffer.oldestTime(), 0.003);
  QCOMPARE(buffer.newestTime(), 0.007);
  for (int i = 0; i < 5; ++i) QCOMPARE(buffer.value(kChannelCount - 1, i), double(i + 3));
  std::array<SampleSpan, 2> spans;
  const int n = buffer.spans(4, {0, buffer.size()}, spans);
  QCOMPARE(n, 2);  // 3 4 | 5 6 7 in storage order after the wrap
  std::vector<double> seen;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < spans[k].count; ++i) seen.push_back(spans[k].value[i]);
  QCOMPARE(seen, (std::vector<double>{3, 4, 5, 6, 7}));
}

void TestPlots::ringRefusesOlderSample() {
  PlotBuffer buffer(0.01, 1000);
  QVERIFY(buffer.push(1.0, filled(1)));
  QVERIFY(!buffer.push(0.5, filled(2)));
  QVERIFY(buffer.push(1.0, filled(3)));  // equal time is allowed
  QCOMPARE(buffer.size(), 2);
}

void TestPlots::windowQueryIsInclusive() {
  PlotBuffer buffer(0.005, 1000);
  for (int i = 0; i < 8; ++i) buffer.push(i * 0.001, filled(i));
  const IndexRange r = buffer.window(0.005, 0.006);
  QCOMPARE(r.count(), 2);
  QCOMPARE(buffer.time(r.first), 0.005);
  QCOMPARE(buffer.time(r.last - 1), 0.006);
  QCOMPARE(buffer.window(0.0, 0.0025).count(), 0);  // overwritten already
  QCOMPARE(buffer.window(0.0, 1.0).count(), 5);
  QCOMPARE(buffer.window(0.02, 0.03).count(), 0);
  QCOMPARE(buffer.window(0.006, 0.005).count(), 0);
}

void TestPlots::copyRangeKeepsSamples() {
  PlotBuffer buffer(0.005, 1000);
  for (int i = 0; i < 8; ++i) buffer.push(i * 0.001, filled(i));
  const PlotBuffer copy = buffer.copyRange({1, 4});
  QCOMPARE(copy.size(), 3);
  QCOMPARE(copy.time(0), 0.004);
  QCOMPARE(copy.value(10, 2), 6.0);
}

void TestPlots::spikeSurvivesAnyZoom() {
  const int n = 100000;
  std::vector<double> t(n), v(n, 0.0);
  for (int i = 0; i < n; ++i) t[static_cast<std::size_t>(i)] = i * 0.001;
  v[43210] = 5.0;
  v[77777] = -3.0;
  for (int columns : {1, 3, 100, 640, 1920, 200000}) {
    QList<QPointF> out;
    decimateMinMax(t.data(), v.data(), n, t.front(), t.back(), columns, out);
    QVERIFY2(out.contains(QPointF(t[43210], 5.0)), qPrintable(QString("columns %1").arg(columns)));
    QVERIFY2(out.contains(QPointF(t[77777], -3.0)), qPrintable(QString("columns %1").arg(columns)));
  }
  // Zoomed in to a window around the spike only.
  QList<QPointF> out;
  decimateMinMax(t.data(), v.data(), n, 43.0, 43.5, 50, out);
  QVERIFY(out.contains(QPointF(t[43210], 5.0)));
}

void TestPlots::decimationStaysInBounds() {
  const int n = 20000;
  std::vector<double> t(n), v(n);
  QRandomGenerator random(42);
  for (int i = 0; i < n; ++i) {
    t[static_cast<std::size_t>(i)] = 10.0 + i * 0.001;
    v[static_cast<std::size_t>(i)] = random.bounded(2.0) - 1.0;
  }
  const double lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
  for (int columns : {1, 7, 500, 1000}) {
    QList<QPointF> out;
    decimateMinMax(t.data(), v.data(), n, t.front(), t.back(), columns, out);
    QVERIFY(out.size() <= 2 * columns + 2);
    QCOMPARE(out.first(), QPointF(t.front(), v.front()));
    QCOMPARE(out.last(), QPointF(t.back(), v.back()));
    for (int i = 0; i < out.size(); ++i) {
      QVERIFY(out[i].y() >= lo && out[i].y() <= hi);
      QVERIFY(out[i].x() >= t.front() && out[i].x() <= t.back());
      if (i > 0) QVERIFY(out[i].x() > out[i - 1].x());  // strictly increasing time
      const auto k = static_cast<std::size_t>(std::lround((out[i].x() - 10.0) / 0.001));
      QCOMPARE(out[i].y(), v[k]);  // every point is an input sample
    }
  }
  // Per column at most two points: count them per column for a mid-size zoom.
  QList<QPointF> out;
  const int columns = 300;
  decimateMinMax(t.data(), v.data(), n, t.front(), t.back(), columns, out);
  std::vector<int> per_column(columns, 0);
  for (const QPointF& p : out)
    ++per_column[static_cast<std::size_t>(
        std::min(columns - 1, int((p.x() - t.front()) * (columns / (t.back() - t.front())))))];
  per_column.front() -= 1;  // the first and last sample may come on top
  per_column.back() -= 1;
  for (int count : per_column) QVERIFY(count <= 2);
  // Samples outside the window and non-finite values are left out.
  v[100] = std::nan("");
  decimateMinMax(t.data(), v.data(), n, t[50], t[150], 10, out);
  QCOMPARE(out.first().x(), t[50]);
  QCOMPARE(out.last().x(), t[150]);
  for (const QPointF& p : out) QVERIFY(std::isfinite(p.y()));
  decimateMinMax(t.data(), v.data(), 0, 0, 1, 10, out);
  QVERIFY(out.isEmpty());
}

void TestPlots::decimationAcrossSpansMatchesOneRun() {
  const int n = 5000;
  std::vector<double> t(n), v(n);
  for (int i = 0; i < n; ++i) {
    t[static_cast<std::size_t>(i)] = i * 0.001;
    v[static_cast<std::size_t>(i)] = std::sin(i * 0.37) * (i % 97 == 0 ? 4 : 1);
  }
  QList<QPointF> whole, pieces;
  decimateMinMax(t.data(), v.data(), n, 0, t.back(), 123, whole);
  MinMaxDecimator decimator;
  decimator.begin(0, t.back(), 123, pieces);
  decimator.add(t.data(), v.data(), 1777);
  decimator.add(t.data() + 1777, v.data() + 1777, n - 1777);
  decimator.finish();
  QCOMPARE(pieces, whole);
}

void TestPlots::simplifyKeepsLineWithinTolerance() {
  QList<QPointF> input;
  for (int i = 0; i < 4000; ++i) input.append(QPointF(i * 0.001, std::sin(i * 0.002) + (i == 2500 ? 0.05 : 0.0)));
  QList<QPointF> output = input;
  const double tolerance = 0.01;
  simplifyWithin(output, tolerance);
  QVERIFY(output.size() < input.size() / 20);  // a smooth curve needs few points
  QCOMPARE(output.first(), input.first());
  QCOMPARE(output.last(), input.last());
  QVERIFY(output.contains(input[2500]));  // a spike of 5 x tolerance stays
  // Every input point lies within tolerance (vertically) of the polyline through the output.
  int segment = 0;
  for (const QPointF& p : input) {
    while (output[segment + 1].x() < p.x()) ++segment;
    const QPointF a = output[segment], b = output[segment + 1];
    const double y = a.y() + (b.y() - a.y()) * (p.x() - a.x()) / (b.x() - a.x());
    QVERIFY2(std::abs(y - p.y()) <= tolerance + 1e-12, qPrintable(QString("x %1").arg(p.x())));
  }
  for (int i = 1; i < output.size(); ++i) QVERIFY(output[i].x() > output[i - 1].x());
  for (const QPointF& p : output) QVERIFY(input.contains(p));  // only input points
  // Two points, or no tolerance: unchanged.
  QList<QPointF> two{{0, 0}, {1, 1}};
  simplifyWithin(two, 1.0);
  QCOMPARE(two.size(), 2);
  QList<QPointF> same = input;
  simplifyWithin(same, 0.0);
  QCOMPARE(same, input);
}

void TestPlots::autoScaleHasHysteresis() {
  AutoScale scale(0.02);
  QVERIFY(scale.update(-1, 1));
  const double lower = scale.lower(), upper = scale.upper();
  QVERIFY(lower < -1 && upper > 1);
  QVERIFY(!scale.update(-0.8, 0.9));  // data inside, more than a third used: no change
  QCOMPARE(scale.lower(), lower);
  QVERIFY(scale.update(-1, 1.5));  // leaves the range: grows at once
  QVERIFY(scale.upper() > 1.5);
  QVERIFY(scale.update(0.1, 0.2));  // uses far less than a third: shrinks
  QVERIFY(scale.lower() < 0.1 && scale.upper() > 0.2 && scale.upper() - scale.lower() < 0.2);
  QVERIFY(scale.update(3, 3));  // a constant gets the minimum span
  QVERIFY(scale.upper() - scale.lower() >= 0.02);
}

void TestPlots::csvHasHeaderWithUnitsAndRows() {
  PlotBuffer buffer(1, 1000);
  ChannelValues values = filled(0);
  values[static_cast<std::size_t>(channelOf(Signal::kPositionMeasured, 0))] = 0.5;
  values[static_cast<std::size_t>(channelOf(Signal::kVelocityMeasured, 2))] = -1.25;
  values[static_cast<std::size_t>(channelOf(Signal::kTorqueExternal, 6))] = 3;
  buffer.push(0.001, values);
  buffer.push(0.002, filled(2));
  QTemporaryDir dir;
  const QString path = dir.filePath("plots.csv");
  const std::vector<int> channels{channelOf(Signal::kPositionMeasured, 0), channelOf(Signal::kVelocityMeasured, 2),
                                  channelOf(Signal::kTorqueExternal, 6)};
  QString error;
  QVERIFY2(writeCsv(buffer, {0, 2}, channels, path, &error), qPrintable(error));
  QCOMPARE(readAll(path), QByteArray("time_s,q_J1_rad,dq_J3_rad_per_s,tau_ext_J7_Nm\n"
                                     "0.001,0.5,-1.25,3\n"
                                     "0.002,2,2,2\n"));
  QVERIFY(!writeCsv(buffer, {0, 0}, channels, path, &error));
  QVERIFY(error.contains("no samples"));
}

void TestPlots::csvReplacesFileOnlyOnSuccess() {
  PlotBuffer buffer(5, 1000);
  for (int i = 0; i < 3000; ++i) buffer.push(i / 1000.0, filled(i));
  QTemporaryDir dir;
  const QString path = dir.filePath("plots.csv");
  writeFile(path, "old contents\n");
  QString error;
  // Cancelled half-way: the old file stays, no temporary file is left behind.
  const bool ok = writeCsv(buffer, {0, buffer.size()}, {0, 1}, path, &error, [](int rows) { return rows < 2000; });
  QVERIFY(!ok);
  QVERIFY(error.contains("cancelled"));
  QCOMPARE(readAll(path), QByteArray("old contents\n"));
  QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"plots.csv"});
  // A folder that does not exist: a clear message.
  QVERIFY(!writeCsv(buffer, {0, buffer.size()}, {0}, dir.filePath("missing/plots.csv"), &error));
  QVERIFY(error.contains("Cannot write"));
  // Success replaces the file.
  QVERIFY2(writeCsv(buffer, {0, buffer.size()}, {0, 1}, path, &error), qPrintable(error));
  const QList<QByteArray> lines = readAll(path).split('\n');
  QCOMPARE(lines.size(), 3000 + 2);  // header, rows, trailing empty piece
  QCOMPARE(lines[0], QByteArray("time_s,q_J1_rad,q_J2_rad"));
  QCOMPARE(lines[3000], QByteArray("2.999,2999,2999"));
}

void TestPlots::freezeStopsUpdates() {
  PlotsWidget widget;
  widget.resize(900, 700);
  widget.show();
  QVERIFY(QTest::qWaitForWindowExposed(&widget));
  const std::vector<StateSample> first = ramp(0.0, 2000);
  widget.addSamples(first.data(), int(first.size()));
  widget.redraw();
  QVERIFY(!widget.canvas(Quantity::kPosition).seriesPoints(0).isEmpty());
  // x is drawn relative to the newest sample: the window is [-10 s, 0].
  QCOMPARE(widget.canvas(Quantity::kPosition).seriesPoints(0).last().x(), 0.0);
  QCOMPARE(widget.canvas(Quantity::kPosition).seriesPoints(0).first().x(), -first.back().time);

  widget.setFrozen(true);  // draws the snapshot once
  QVERIFY(widget.isFrozen());
  const QList<QPointF> before = widget.canvas(Quantity::kPosition).seriesPoints(0);
  QCOMPARE(before.last().x(), 0.0);
  const std::vector<StateSample> more = ramp(2.0, 3000);
  widget.addSamples(more.data(), int(more.size()));
  widget.redraw();
  QCOMPARE(widget.canvas(Quantity::kPosition).seriesPoints(0), before);
  widget.setSignalVisible(Signal::kPositionCommanded, true);  // re-draws the frozen view only
  QCOMPARE(widget.canvas(Quantity::kPosition).seriesPoints(0), before);
  QCOMPARE(widget.buffer().newestTime(), more.back().time);  // recording went on

  auto boxes = widget.findChildren<QPushButton*>();
  const auto freeze = std::find_if(boxes.begin(), boxes.end(), [](QPushButton* b) { return b->isCheckable(); });
  QVERIFY(freeze != boxes.end());
  QCOMPARE((*freeze)->text(), QString("Resume"));
  (*freeze)->click();  // resume through the button
  QVERIFY(!widget.isFrozen());
  widget.redraw();
  const QList<QPointF> after = widget.canvas(Quantity::kPosition).seriesPoints(0);
  QCOMPARE(after.last().x(), 0.0);
  QCOMPARE(after.first().x(), -(more.back().time - 0.0));  // 0 .. 4.999 s now fills the window
}

void TestPlots::signalSelectionChangesVisibleSeries() {
  PlotsWidget widget;
  widget.resize(900, 700);
  widget.show();
  const std::vector<StateSample> samples = ramp(0.0, 500);
  widget.addSamples(samples.data(), int(samples.size()));
  widget.redrawNow();
  QCOMPARE(widget.visibleSeriesCount(), 21);  // position, velocity, torque measured x 7 joints
  widget.setSignalVisible(Signal::kTorqueExternal, true);
  QCOMPARE(widget.visibleSeriesCount(), 28);
  QVERIFY(widget.canvas(Quantity::kTorque).isSeriesVisible(channelOf(Signal::kTorqueExternal, 3)));
  QVERIFY(!widget.canvas(Quantity::kTorque).seriesPoints(channelOf(Signal::kTorqueExternal, 3)).isEmpty());

  QCheckBox* j2 = nullptr;
  for (QCheckBox* box : widget.findChildren<QCheckBox*>())
    if (box->text() == "J2") j2 = box;
  QVERIFY(j2 != nullptr);
  j2->click();  // untick joint 2 in the chooser
  QCOMPARE(widget.visibleSeriesCount(), 24);
  QVERIFY(!widget.canvas(Quantity::kVelocity).isSeriesVisible(channelOf(Signal::kVelocityMeasured, 1)));

  widget.setJointCount(6);  // a 6-axis arm: joint 7 leaves every chart
  QCOMPARE(widget.visibleSeriesCount(), 20);
  QVERIFY(!widget.canvas(Quantity::kPosition).isSeriesVisible(channelOf(Signal::kPositionMeasured, 6)));
}

// The control strip is one row and the charts are compact: all three fit a ~380 px dock, with plot
// areas of equal width (a fixed value-label margin), so their left edges line up.
void TestPlots::chartsFitCompactDockAndLineUp() {
  PlotsWidget widget;
  QVERIFY2(widget.minimumSizeHint().height() <= 330, qPrintable(QString::number(widget.minimumSizeHint().height())));
  widget.resize(1200, 330);
  widget.show();
  QVERIFY(QTest::qWaitForWindowExposed(&widget));
  const int width = widget.canvas(Quantity::kPosition).plotWidth();
  for (int q = 0; q < kQuantityCount; ++q) {
    PlotCanvas& canvas = widget.canvas(static_cast<Quantity>(q));
    QCOMPARE(canvas.plotWidth(), width);
    QCOMPARE(canvas.widget()->x(), widget.canvas(Quantity::kPosition).widget()->x());
    QVERIFY2(canvas.plotHeight() >= 50, qPrintable(QString::number(canvas.plotHeight())));
  }
  QVERIFY(width > 1000);
}

// The traces are drawn by our own layer inside the chart: a line at y = 5 spans the plot area's middle,
// a line from y = 2 to y = 8 rises, a non-finite sample leaves a gap, and a hidden trace draws nothing.
void TestPlots::tracesAreDrawnWhereTheAxesSay() {
  ChartCanvas canvas;
  QWidget* view = canvas.widget();
  view->resize(500, 260);
  view->show();
  QVERIFY(QTest::qWaitForWindowExposed(view));
  canvas.addSeries(0, QStringLiteral("middle"), QColor(220, 0, 0), Qt::SolidLine);
  canvas.addSeries(1, QStringLiteral("rising"), QColor(0, 0, 220), Qt::SolidLine);
  canvas.addSeries(2, QStringLiteral("hidden"), QColor(0, 200, 0), Qt::SolidLine);
  canvas.setXRange(0, 10);
  canvas.setYRange(0, 10);
  canvas.setSeries(0, {{0, 5}, {10, 5}});
  const double nan = std::nan("");
  canvas.setSeries(1, {{0, 2}, {2, 2}, {5, nan}, {8, 8}, {10, 8}});
  canvas.setSeriesVisible(2, false);
  canvas.setSeries(2, {{0, 1}, {10, 9}});
  QVERIFY(canvas.seriesPoints(2).isEmpty());
  QCOMPARE(canvas.visibleSeriesCount(), 2);
  QCOMPARE(canvas.seriesPoints(1).size(), 5);

  const QImage image = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
  auto red = [&](int x, int y) { const QColor c = image.pixelColor(x, y); return c.red() - c.green() > 60; };
  auto blue = [&](int x, int y) { const QColor c = image.pixelColor(x, y); return c.blue() - c.red() > 60; };
  auto green = [&](int x, int y) { const QColor c = image.pixelColor(x, y); return c.green() - c.red() > 60; };
  auto rowOf = [&](int x, const auto& is) {
    for (int y = 0; y < image.height(); ++y)
      if (is(x, y)) return y;
    return -1;
  };
  // The red line marks the plot area's extent in x, and its middle in y.
  int left = -1, right = -1;
  for (int x = 0; x < image.width(); ++x)
    if (rowOf(x, red) >= 0) {
      if (left < 0) left = x;
      right = x;
    }
  QVERIFY2(left >= 0 && right - left > 300, qPrintable(QStringLiteral("red from %1 to %2").arg(left).arg(right)));
  QVERIFY(std::abs((right - left) - canvas.plotWidth()) <= 2);
  auto column = [&](double x) { return left + static_cast<int>(std::lround(x / 10 * (right - left))); };
  const int middle = rowOf(column(5), red);
  const double pixels_per_unit = canvas.plotHeight() / 10.0;
  const int low = rowOf(column(1), blue), high = rowOf(column(9), blue);
  QVERIFY(low >= 0 && high >= 0);
  QVERIFY2(std::abs(low - middle - 3 * pixels_per_unit) <= 2, qPrintable(QStringLiteral("%1 %2").arg(low).arg(middle)));
  QVERIFY2(std::abs(middle - high - 3 * pixels_per_unit) <= 2, qPrintable(QStringLiteral("%1 %2").arg(high).arg(middle)));
  QCOMPARE(rowOf(column(5), blue), -1);  // the gap of the non-finite sample
  for (int x = left; x <= right; x += 10) QCOMPARE(rowOf(x, green), -1);
}

void TestPlots::frozenViewExportHasShownSeries() {
  PlotsWidget widget;
  widget.setWindowSeconds(2);
  const std::vector<StateSample> samples = ramp(0.0, 5001);  // 0 .. 5 s
  widget.addSamples(samples.data(), int(samples.size()));
  QTemporaryDir dir;
  QString error;
  QVERIFY(!widget.exportCsv(dir.filePath("view.csv"), PlotsWidget::ExportScope::kFrozenView, &error));
  QVERIFY(error.contains("Freeze"));
  widget.setJointCount(6);
  widget.setFrozen(true);
  QVERIFY2(widget.exportCsv(dir.filePath("view.csv"), PlotsWidget::ExportScope::kFrozenView, &error), qPrintable(error));
  QList<QByteArray> lines = readAll(dir.filePath("view.csv")).split('\n');
  QCOMPARE(lines[0].split(',').size(), 1 + 18);  // time + 3 signals x 6 joints
  QCOMPARE(lines.size(), 2001 + 2);             // 3.000 .. 5.000 s inclusive
  QVERIFY(lines[1].startsWith("3,"));
  QVERIFY2(widget.exportCsv(dir.filePath("all.csv"), PlotsWidget::ExportScope::kWholeBuffer, &error), qPrintable(error));
  lines = readAll(dir.filePath("all.csv")).split('\n');
  QCOMPARE(lines[0].split(',').size(), 1 + 6 * 6);  // every signal of the arm's 6 joints
  QCOMPARE(lines.size(), 5001 + 2);
}

void TestPlots::jointTorquesAreJTransposeF() {
  // xMate7 Pro at q = 0 stands straight up: joints 1, 3, 5, 7 turn about the base z axis, joints
  // 2, 4, 6 about y at heights 0.404, 0.8415, 1.254 m; the flange is at 1.5295 m (SPEC DH table).
  // A force Fx at the flange gives joint k (about y at height h_k) a torque Fx * (1.5295 - h_k);
  // a moment Mz reaches only the z joints.
  ExternalTorqueMap map(xmate::XMATE7_PRO);
  const std::array<double, 6> wrench{10, 0, 0, 0, 0, 2};
  const std::array<double, 7> tau = map.jointTorques({}, wrench);
  const std::array<double, 7> expected{2, 10 * (1.5295 - 0.404), 2, 10 * (1.5295 - 0.8415), 2, 10 * 0.2755, 2};
  for (int i = 0; i < 7; ++i)
    QVERIFY2(std::abs(tau[i] - expected[i]) < 1e-9, qPrintable(QString("J%1: %2 vs %3").arg(i + 1).arg(tau[i]).arg(expected[i])));
  // A tool 0.1 m out along the flange z axis lengthens every lever arm by 0.1 m.
  std::array<double, 16> tool{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0.1, 0, 0, 0, 1};
  map.setTool(tool);
  const std::array<double, 7> with_tool = map.jointTorques({}, wrench);
  QVERIFY(std::abs(with_tool[1] - (expected[1] + 1.0)) < 1e-9);
  QVERIFY(std::abs(with_tool[5] - (expected[5] + 1.0)) < 1e-9);
}

void TestPlots::widgetMapsExternalWrench() {
  PlotsWidget widget;
  widget.setExternalTorqueMap(std::make_unique<ExternalTorqueMap>(xmate::XMATE7_PRO));
  StateSample sample = sampleAt(0.5, 0);
  sample.tau_ext_in_base = {10, 0, 0, 0, 0, 2};
  widget.addSamples(&sample, 1);
  QCOMPARE(widget.buffer().size(), 1);
  QVERIFY(std::abs(widget.buffer().value(channelOf(Signal::kTorqueExternal, 1), 0) - 11.255) < 1e-9);
  QCOMPARE(widget.buffer().value(channelOf(Signal::kTorqueExternal, 0), 0), 2.0);
}

QTEST_MAIN(TestPlots)
#include "test_plots.moc"
