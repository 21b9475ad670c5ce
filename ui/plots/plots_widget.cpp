// SPDX-License-Identifier: Apache-2.0
// PlotsWidget (plots_widget.h), data path: recording, the timed redraw (window query, min/max
// decimation, one replace per series), auto-scaling, freeze and export.
#include "plots/plots_widget.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "plots/csv_export.h"

namespace rci::ui::plots {

PlotsWidget::PlotsWidget(QWidget* parent) : QWidget(parent), buffer_(kBufferSeconds, kSampleRateHz) {
  joint_on_.fill(true);
  signal_on_[static_cast<int>(Signal::kPositionMeasured)] = true;
  signal_on_[static_cast<int>(Signal::kVelocityMeasured)] = true;
  signal_on_[static_cast<int>(Signal::kTorqueMeasured)] = true;
  buildUi();
  declareSeries();
  applyVisibility();
  timer_.setInterval(kRedrawIntervalMs);
  connect(&timer_, &QTimer::timeout, this, &PlotsWidget::redraw);
  timer_.start();
}

PlotsWidget::~PlotsWidget() = default;

void PlotsWidget::addSamples(const xmate::client::StateSample* samples, int count) {
  std::array<double, 7> tau_ext{};
  for (int i = 0; i < count; ++i) {
    const xmate::client::StateSample& s = samples[i];
    if (map_) tau_ext = map_->jointTorques(s.q, s.tau_ext_in_base);
    channelsOf(s, tau_ext, scratch_values_);
    buffer_.push(s.time, scratch_values_);
  }
}

void PlotsWidget::clear() {
  buffer_.clear();
  for (AutoScale& scale : scales_) scale.reset();
  if (!isFrozen()) redrawNow();
}

void PlotsWidget::setExternalTorqueMap(std::unique_ptr<ExternalTorqueMap> map) { map_ = std::move(map); }

bool PlotsWidget::channelVisible(int channel) const {
  const int joint = jointOfChannel(channel);
  return joint < joint_count_ && joint_on_[static_cast<std::size_t>(joint)] &&
         signal_on_[static_cast<std::size_t>(signalOfChannel(channel))];
}

std::vector<int> PlotsWidget::visibleChannels() const {
  std::vector<int> channels;
  for (int c = 0; c < kChannelCount; ++c)
    if (channelVisible(c)) channels.push_back(c);
  return channels;
}

std::vector<int> PlotsWidget::allChannels() const {
  std::vector<int> channels;
  for (int c = 0; c < kChannelCount; ++c)
    if (jointOfChannel(c) < joint_count_) channels.push_back(c);
  return channels;
}

int PlotsWidget::visibleSeriesCount() const {
  int count = 0;
  for (const auto& canvas : canvases_) count += canvas->visibleSeriesCount();
  return count;
}

void PlotsWidget::applyVisibility() {
  for (int c = 0; c < kChannelCount; ++c) canvas(quantityOf(signalOfChannel(c))).setSeriesVisible(c, channelVisible(c));
  for (AutoScale& scale : scales_) scale.reset();
}

void PlotsWidget::redraw() {
  if (isFrozen() || !isVisible()) return;
  redrawNow();
}

void PlotsWidget::redrawNow() {
  const PlotBuffer& source = frozen_ ? *frozen_ : buffer_;
  const double x1 = source.empty() ? window_seconds_ : source.newestTime();
  const double x0 = x1 - window_seconds_;
  const IndexRange range = source.window(x0, x1);
  for (int q = 0; q < kQuantityCount; ++q) drawQuantity(static_cast<Quantity>(q), source, range, x0, x1);
  updateStatus();
}

void PlotsWidget::drawQuantity(Quantity quantity, const PlotBuffer& source, IndexRange range, double x0, double x1) {
  // The axes stay put, so their labels do not flicker and Qt Charts does not relayout them every
  // frame: x is drawn as seconds relative to the newest sample, [-window, 0], and the value axis moves
  // only on an auto-scale step, before the points are replaced.
  PlotCanvas& target = canvas(quantity);
  const int columns = target.plotWidth();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int c = 0; c < kChannelCount; ++c) {
    if (quantityOf(signalOfChannel(c)) != quantity || !channelVisible(c)) continue;
    QList<QPointF>& points = points_[static_cast<std::size_t>(c)];
    std::array<SampleSpan, 2> spans;
    const int n = source.spans(c, range, spans);
    decimator_.begin(x0, x1, columns, points);
    for (int k = 0; k < n; ++k) decimator_.add(spans[k].time, spans[k].value, spans[k].count);
    decimator_.finish();
    for (const QPointF& p : std::as_const(points)) {
      lo = std::min(lo, p.y());
      hi = std::max(hi, p.y());
    }
  }
  AutoScale& scale = scales_[static_cast<std::size_t>(quantity)];
  if (scale.update(lo, hi)) target.setYRange(scale.lower(), scale.upper());
  target.setXRange(x0 - x1, 0);
  const double tolerance = kToleranceInPixels * (scale.upper() - scale.lower()) / target.plotHeight();
  for (int c = 0; c < kChannelCount; ++c) {
    if (quantityOf(signalOfChannel(c)) != quantity || !channelVisible(c)) continue;
    QList<QPointF>& points = points_[static_cast<std::size_t>(c)];
    simplifyWithin(points, tolerance);
    for (QPointF& p : points) p.rx() -= x1;
    target.setSeries(c, points);
  }
}

void PlotsWidget::setFrozen(bool frozen) {
  if (frozen == isFrozen()) return;
  if (frozen) {
    frozen_ = std::make_unique<PlotBuffer>(buffer_.copyRange({0, buffer_.size()}));
  } else {
    frozen_.reset();
  }
  updateFreezeControls();
  redrawNow();
  emit frozenChanged(frozen);
}

bool PlotsWidget::exportCsv(const QString& path, ExportScope scope, QString* error) const {
  if (scope == ExportScope::kWholeBuffer) return writeCsv(buffer_, {0, buffer_.size()}, allChannels(), path, error);
  if (!frozen_) {
    if (error != nullptr) *error = QStringLiteral("The view is not frozen: press Freeze first, then export the view.");
    return false;
  }
  const double x1 = frozen_->empty() ? 0 : frozen_->newestTime();
  const std::vector<int> channels = visibleChannels();
  if (channels.empty()) {
    if (error != nullptr) *error = QStringLiteral("No series is shown: tick at least one joint and one signal.");
    return false;
  }
  return writeCsv(*frozen_, frozen_->window(x1 - window_seconds_, x1), channels, path, error);
}

}  // namespace rci::ui::plots
