// SPDX-License-Identifier: Apache-2.0
// rci-bench-plot: ms per redraw frame of the live plots (7 joints x 3 signals, 1 kHz, 10 s window) against
// Qt Charts' own QLineSeries (fed raw or decimated points), and CPU share while streaming. Results: docs/performance.md ("Live plots").
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QElapsedTimer>
#include <QImage>
#include <QLineSeries>
#include <QPainter>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <time.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <memory>
#include <string>
#include <vector>

#include "plots/decimation.h"
#include "plots/plots_widget.h"

using namespace rci::ui::plots;
using xmate::client::StateSample;

namespace {

constexpr double kWindowSeconds = 10;
constexpr int kWidth = 1280, kHeight = 900;  // the plot area of a full-HD window

struct Options {
  bool quick = false;
  int frames = 60;
  double stream_seconds = 10;
  double noise_nm = 0;  // amplitude of sensor-like noise on the torques
  bool ours_only = false;  // skip the reference and the streaming part (for profiling)
  const char* screenshot = nullptr;  // PNG of the widget at the end of the streaming part
};

Options g_options;

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      options.quick = true;
      options.frames = 10;
      options.stream_seconds = 3;
    } else if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
      options.stream_seconds = std::max(1.0, std::atof(argv[++i]));
    } else if (std::strcmp(argv[i], "--screenshot") == 0 && i + 1 < argc) {
      options.screenshot = argv[++i];
    } else if (std::strcmp(argv[i], "--ours-only") == 0) {
      options.ours_only = true;
    } else if (std::strcmp(argv[i], "--noise") == 0 && i + 1 < argc) {
      options.noise_nm = std::max(0.0, std::atof(argv[++i]));
    } else if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      options.frames = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "usage: rci-bench-plot [--quick] [--frames N] [--seconds S] [--noise NM] [--ours-only] [--screenshot FILE.png]\n");
      std::exit(2);
    }
  }
  return options;
}

// Synthetic 1 kHz state: smooth joint motion, smooth torques with a one-sample +40 Nm spike every
// 0.37 s, and (--noise) a pseudo-random torque noise of that amplitude.
StateSample syntheticSample(long index) {
  StateSample s;
  s.time = index / 1000.0;
  const bool spike = index % 370 == 0;
  for (int j = 0; j < 7; ++j) {
    const double w = 2 * std::numbers::pi * (0.2 + 0.07 * j);
    s.q[j] = 0.6 * std::sin(w * s.time + j);
    s.q_c[j] = s.q[j] + 0.001;
    s.dq_m[j] = 0.6 * w * std::cos(w * s.time + j);
    const double noise = g_options.noise_nm * std::sin(977.0 * index + j);  // aliased: looks random
    s.tau_m[j] = 12 * std::sin(0.5 * w * s.time) + noise + (spike ? 40 : 0);
    s.tau_c[j] = s.tau_m[j] - 0.2;
  }
  s.tau_ext_in_base = {2 * std::sin(s.time), 0, 1, 0, 0, 0.1};
  return s;
}

// CPU time of this thread, ms: the work a frame costs, whatever else the machine is doing.
double threadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

double cpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct FrameStats {
  double update_ms = 0, update_cpu_ms = 0;  // building and handing over the points (wall, thread CPU)
  double paint_ms = 0, paint_cpu_ms = 0;    // rendering the three charts
  double points = 0;                        // points handed to the charts per frame
  std::array<double, kQuantityCount> points_per_chart{};
  double total() const { return update_ms + paint_ms; }
  double totalCpu() const { return update_cpu_ms + paint_cpu_ms; }
  void divide(int frames) {
    update_ms /= frames;
    update_cpu_ms /= frames;
    paint_ms /= frames;
    paint_cpu_ms /= frames;
    points /= frames;
    for (double& p : points_per_chart) p /= frames;
  }
};

// Times one step of a frame into wall and CPU accumulators.
template <typename Step>
void timed(double& wall_ms, double& cpu_ms, Step step) {
  QElapsedTimer clock;
  const double cpu0 = threadCpuMs();
  clock.start();
  step();
  wall_ms += clock.nsecsElapsed() * 1e-6;
  cpu_ms += threadCpuMs() - cpu0;
}

const std::array<Signal, 3> kBenchSignals{Signal::kPositionMeasured, Signal::kVelocityMeasured, Signal::kTorqueMeasured};

void paintCharts(const std::array<QWidget*, kQuantityCount>& charts, QImage& image) {
  for (QWidget* chart : charts) {
    QPainter painter(&image);
    chart->render(&painter);
  }
}

// Our path: the production PlotsWidget (decimate + trace layer) then painting its three charts.
FrameStats benchOurs(const Options& options, long& next) {
  PlotsWidget widget;
  widget.resize(kWidth, kHeight);
  widget.setWindowSeconds(static_cast<int>(kWindowSeconds));
  widget.show();
  std::vector<StateSample> batch;
  for (; next < 10000; ++next) batch.push_back(syntheticSample(next));
  widget.addSamples(batch.data(), static_cast<int>(batch.size()));
  widget.redrawNow();
  QApplication::processEvents();
  std::array<QWidget*, kQuantityCount> charts{};
  for (int q = 0; q < kQuantityCount; ++q) charts[q] = widget.canvas(static_cast<Quantity>(q)).widget();
  QImage image(charts[0]->size(), QImage::Format_ARGB32_Premultiplied);
  FrameStats stats;
  for (int frame = 0; frame < options.frames; ++frame) {
    batch.clear();
    for (int i = 0; i < 33; ++i, ++next) batch.push_back(syntheticSample(next));
    widget.addSamples(batch.data(), static_cast<int>(batch.size()));
    timed(stats.update_ms, stats.update_cpu_ms, [&] { widget.redrawNow(); });
    timed(stats.paint_ms, stats.paint_cpu_ms, [&] { paintCharts(charts, image); });
    for (int q = 0; q < kQuantityCount; ++q)
      for (Signal s : kBenchSignals)
        for (int j = 0; j < 7; ++j) {
          const auto n = widget.canvas(static_cast<Quantity>(q)).seriesPoints(channelOf(s, j)).size();
          stats.points += n;
          stats.points_per_chart[q] += n;
        }
  }
  stats.divide(options.frames);
  return stats;
}

// One chart of the references: textbook Qt Charts -- a QChart with fixed value axes and one
// QLineSeries per joint, antialiasing and OpenGL off, refreshed with one replace() per series.
struct SeriesChart {
  QChart* chart = new QChart;
  QChartView* view = nullptr;
  std::array<QLineSeries*, 7> series{};

  SeriesChart(QWidget* parent, double y_range) {
    chart->legend()->hide();
    chart->setAnimationOptions(QChart::NoAnimation);
    auto* x_axis = new QValueAxis;
    auto* y_axis = new QValueAxis;
    x_axis->setRange(-kWindowSeconds, 0);
    y_axis->setRange(-y_range, y_range);
    chart->addAxis(x_axis, Qt::AlignBottom);
    chart->addAxis(y_axis, Qt::AlignLeft);
    for (int j = 0; j < 7; ++j) {
      series[j] = new QLineSeries;
      series[j]->setUseOpenGL(false);
      QPen pen(jointColour(j));
      pen.setWidthF(1.2);
      pen.setCosmetic(true);
      series[j]->setPen(pen);
      chart->addSeries(series[j]);
      series[j]->attachAxis(x_axis);
      series[j]->attachAxis(y_axis);
    }
    view = new QChartView(chart, parent);
    view->setRenderHint(QPainter::Antialiasing, false);
  }
};

// The references: the same data and layout drawn with Qt Charts' own QLineSeries, handed either every
// raw point of the window (naive) or the points our decimation and half-pixel simplification keep
// (the production path before the trace layer).
FrameStats benchQtChartsSeries(const Options& options, long& next, bool decimate) {
  QWidget host;
  auto* layout = new QVBoxLayout(&host);
  std::vector<std::unique_ptr<SeriesChart>> charts_owned;
  std::array<QWidget*, kQuantityCount> charts{};
  const std::array<double, kQuantityCount> y_range{3, 3, 60};
  for (int q = 0; q < kQuantityCount; ++q) {
    charts_owned.push_back(std::make_unique<SeriesChart>(&host, y_range[q]));
    charts[q] = charts_owned.back()->view;
    layout->addWidget(charts[q]);
  }
  host.resize(kWidth, kHeight - 120);  // about the charts' share of PlotsWidget
  host.show();
  PlotBuffer buffer(PlotsWidget::kBufferSeconds, PlotsWidget::kSampleRateHz);
  ChannelValues values{};
  const std::array<double, 7> no_ext{};
  for (long i = next - 10000; i < next; ++i) {
    channelsOf(syntheticSample(i), no_ext, values);
    buffer.push(i / 1000.0, values);
  }
  QApplication::processEvents();
  QImage image(charts[0]->size(), QImage::Format_ARGB32_Premultiplied);
  FrameStats stats;
  QList<QPointF> points;
  MinMaxDecimator decimator;
  for (int frame = 0; frame < options.frames; ++frame) {
    for (int i = 0; i < 33; ++i, ++next) {
      channelsOf(syntheticSample(next), no_ext, values);
      buffer.push(next / 1000.0, values);
    }
    timed(stats.update_ms, stats.update_cpu_ms, [&] {
      const double x1 = buffer.newestTime(), x0 = x1 - kWindowSeconds;
      const IndexRange range = buffer.window(x0, x1);
      for (int q = 0; q < kQuantityCount; ++q) {
        const QRectF area = charts_owned[q]->chart->plotArea();
        for (int j = 0; j < 7; ++j) {
          const int channel = channelOf(kBenchSignals[q], j);
          if (decimate) {
            std::array<SampleSpan, 2> spans;
            const int n = buffer.spans(channel, range, spans);
            decimator.begin(x0, x1, static_cast<int>(area.width()), points);
            for (int k = 0; k < n; ++k) decimator.add(spans[k].time, spans[k].value, spans[k].count);
            decimator.finish();
            simplifyWithin(points, 0.5 * 2 * y_range[q] / area.height());
            for (QPointF& p : points) p.rx() -= x1;
          } else {
            points.clear();
            for (int i = range.first; i < range.last; ++i)
              points.append(QPointF(buffer.time(i) - x1, buffer.value(channel, i)));
          }
          charts_owned[q]->series[j]->replace(points);
          stats.points += points.size();
        }
      }
    });
    timed(stats.paint_ms, stats.paint_cpu_ms, [&] { paintCharts(charts, image); });
  }
  stats.divide(options.frames);
  return stats;
}

// The decimation alone (window query + min/max per column of 21 series), thread CPU ms per frame.
double benchDecimationOnly(const Options& options) {
  PlotBuffer buffer(PlotsWidget::kBufferSeconds, PlotsWidget::kSampleRateHz);
  ChannelValues values{};
  const std::array<double, 7> no_ext{};
  for (long i = 0; i < 10000 + 33L * options.frames; ++i) {
    channelsOf(syntheticSample(i), no_ext, values);
    buffer.push(i / 1000.0, values);
  }
  QList<QPointF> points;
  MinMaxDecimator decimator;
  double cpu_ms = 0, wall_ms = 0;
  for (int frame = 0; frame < options.frames; ++frame) {
    const double x1 = (10000 + 33.0 * frame) / 1000.0, x0 = x1 - kWindowSeconds;
    timed(wall_ms, cpu_ms, [&] {
      const IndexRange range = buffer.window(x0, x1);
      for (Signal s : kBenchSignals)
        for (int j = 0; j < 7; ++j) {
          std::array<SampleSpan, 2> spans;
          const int n = buffer.spans(channelOf(s, j), range, spans);
          decimator.begin(x0, x1, 1150, points);
          for (int k = 0; k < n; ++k) decimator.add(spans[k].time, spans[k].value, spans[k].count);
          decimator.finish();
        }
    });
  }
  return cpu_ms / options.frames;
}

// Counts paint events of the chart views (proof that the streaming phase really draws).
class PaintCounter : public QObject {
 public:
  int count = 0;
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::Paint) ++count;
    return QObject::eventFilter(watched, event);
  }
};

struct StreamStats {
  double cpu_share = 0;  // of one core
  double wall_s = 0;
  long samples = 0;
  int paints = 0;
};

// The real widget, shown, with its own 30 Hz timer; samples arrive in display-rate batches as
// Session::samplesArrived delivers them, with the J^T mapping of the external wrench.
StreamStats benchStreaming(const Options& options) {
  PlotsWidget widget;
  widget.resize(kWidth, kHeight);
  widget.setWindowSeconds(static_cast<int>(kWindowSeconds));
  widget.setExternalTorqueMap(std::make_unique<ExternalTorqueMap>(xmate::XMATE7_PRO));
  widget.show();
  PaintCounter counter;
  for (int q = 0; q < kQuantityCount; ++q) {
    auto* view = widget.canvas(static_cast<Quantity>(q)).widget();
    view->installEventFilter(&counter);
    for (QObject* child : view->children())
      if (child->isWidgetType()) child->installEventFilter(&counter);
  }
  QApplication::processEvents();
  StreamStats stats;
  std::vector<StateSample> batch;
  QElapsedTimer wall;
  QTimer feeder;
  feeder.setTimerType(Qt::PreciseTimer);
  feeder.setInterval(PlotsWidget::kRedrawIntervalMs);
  QObject::connect(&feeder, &QTimer::timeout, [&] {
    const long due = static_cast<long>(wall.nsecsElapsed() / 1000000);  // one sample per elapsed ms
    batch.clear();
    for (; stats.samples < due; ++stats.samples) batch.push_back(syntheticSample(stats.samples));
    widget.addSamples(batch.data(), static_cast<int>(batch.size()));
  });
  const double cpu0 = cpuSeconds();
  wall.start();
  feeder.start();
  QTimer::singleShot(static_cast<int>(options.stream_seconds * 1000), qApp, &QApplication::quit);
  QApplication::exec();
  stats.wall_s = wall.nsecsElapsed() * 1e-9;
  stats.cpu_share = (cpuSeconds() - cpu0) / stats.wall_s;
  stats.paints = counter.count;
  if (options.screenshot != nullptr && !widget.grab().save(QString::fromLocal8Bit(options.screenshot)))
    std::fprintf(stderr, "could not write %s\n", options.screenshot);
  return stats;
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  g_options = parseOptions(argc, argv);
  const Options& options = g_options;
  QApplication app(argc, argv);
  std::printf("rci-bench-plot%s: 7 joints x 3 signals (q, dq, tau measured) at 1 kHz, %.0f s window, %dx%d px, "
              "torque spikes every 0.37 s, torque noise %.2f Nm, platform %s\n",
              options.quick ? " --quick" : "", kWindowSeconds, kWidth, kHeight, options.noise_nm,
              qPrintable(QGuiApplication::platformName()));

  long next = 0;
  const FrameStats ours = benchOurs(options, next);
  if (options.ours_only) {
    std::printf("ours: update %.2f ms (CPU %.2f), paint %.2f ms (CPU %.2f), %.0f points\n", ours.update_ms,
                ours.update_cpu_ms, ours.paint_ms, ours.paint_cpu_ms, ours.points);
    return 0;
  }
  const FrameStats series = benchQtChartsSeries(options, next, true);
  const FrameStats naive = benchQtChartsSeries(options, next, false);
  const double decimation_cpu_ms = benchDecimationOnly(options);
  std::printf("\nper redraw frame, mean of %d frames (ms; wall clock, and CPU time of the GUI thread)\n", options.frames);
  std::printf("                              update wall/cpu   paint wall/cpu   total wall/cpu   points/frame\n");
  auto row = [](const char* name, const FrameStats& s) {
    std::printf("  %-26s %8.2f %7.2f %8.2f %7.2f %8.2f %7.2f %14.0f\n", name, s.update_ms, s.update_cpu_ms, s.paint_ms,
                s.paint_cpu_ms, s.total(), s.totalCpu(), s.points);
  };
  row("ours: decimate + traces", ours);
  row("QLineSeries, decimated", series);
  row("QLineSeries, raw points", naive);
  std::printf("  ours, points per chart: position %.0f, velocity %.0f, torque %.0f\n", ours.points_per_chart[0],
              ours.points_per_chart[1], ours.points_per_chart[2]);
  std::printf("  of ours, the decimation alone: %.2f ms CPU\n", decimation_cpu_ms);
  auto ratio = [&](const char* name, const FrameStats& s) {
    std::printf("  %s / ours: update %.1fx wall, %.1fx CPU; update + paint %.1fx wall, %.1fx CPU\n", name,
                s.update_ms / ours.update_ms, s.update_cpu_ms / ours.update_cpu_ms, s.total() / ours.total(),
                s.totalCpu() / ours.totalCpu());
  };
  ratio("QLineSeries decimated", series);
  ratio("QLineSeries raw", naive);
  auto verdict = [](double ms) { return ms <= 8.0 ? "met" : "NOT met"; };
  std::printf("  target <= 8 ms per frame -- decimate + traces: wall %s, CPU %s; with paint: wall %s, CPU %s\n",
              verdict(ours.update_ms), verdict(ours.update_cpu_ms), verdict(ours.total()), verdict(ours.totalCpu()));

  const StreamStats stream = benchStreaming(options);
  std::printf("\nstreaming %.1f s: %ld samples (%.0f Hz), %d chart paints (%.1f per chart per s), CPU %.1f %% of one core"
              "  target < 30 %% -> %s\n",
              stream.wall_s, stream.samples, stream.samples / stream.wall_s, stream.paints,
              stream.paints / stream.wall_s / kQuantityCount, 100 * stream.cpu_share,
              stream.cpu_share < 0.30 ? "met" : "NOT met");
  return 0;
}
