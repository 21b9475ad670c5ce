// SPDX-License-Identifier: Apache-2.0
// PlotsWidget (plots_widget.h), data path: recording, the timed redraw (window query, min/max
// decimation, one replace per series), auto-scaling, freeze and export.
#include "plots/plots_widget.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "plots/csv_export.h"

namespace rci::ui::plots {

std::vector<int> keptChannels(const PlotSetup& setup) {
  std::vector<int> channels;
  for (Signal signal : setup.offered)
    for (int k = 0; k < componentCount(signal); ++k) channels.push_back(channelOf(signal, k));
  std::sort(channels.begin(), channels.end());
  return channels;
}

PlotsWidget::PlotsWidget(QWidget* parent)
    : QWidget(parent), setup_(xmateSetup()), buffer_(kBufferSeconds, setup_.sample_rate_hz, keptChannels(setup_)) {
  joint_on_.fill(true);
  for (Signal signal : setup_.offered) offered_[static_cast<std::size_t>(signal)] = true;
  for (Signal signal : setup_.ticked) signal_on_[static_cast<std::size_t>(signal)] = true;
  buildUi();
  declareSeries();
  applySetup();
  timer_.setInterval(kRedrawIntervalMs);
  connect(&timer_, &QTimer::timeout, this, &PlotsWidget::redraw);
  timer_.start();
}

PlotsWidget::~PlotsWidget() = default;

void PlotsWidget::configure(const PlotSetup& setup) {
  if (setup == setup_) return;
  const bool was_frozen = isFrozen();
  setup_ = setup;
  offered_.fill(false);
  signal_on_.fill(false);
  for (Signal signal : setup_.offered) offered_[static_cast<std::size_t>(signal)] = true;
  for (Signal signal : setup_.ticked) signal_on_[static_cast<std::size_t>(signal)] = true;
  joint_count_ = std::clamp(setup_.joints, 1, kJointCount);
  buffer_ = PlotBuffer(kBufferSeconds, setup_.sample_rate_hz, keptChannels(setup_));
  frozen_.reset();
  arm_channels_.setCycleSeconds(setup_.cycle_seconds);
  arm_channels_.reset();
  for (AutoScale& scale : scales_) scale.reset();
  applySetup();
  updateFreezeControls();
  redrawNow();
  if (was_frozen) emit frozenChanged(false);
}

void PlotsWidget::addArmSamples(const xmate::arm::ArmSample* samples, int count, const ArmExtras& extras) {
  if (!recordsArmSamples()) return;
  for (int i = 0; i < count; ++i) {
    arm_channels_.map(samples[i], extras, scratch_values_);
    buffer_.push(samples[i].time, scratch_values_);
  }
}

void PlotsWidget::addSamples(const xmate::client::StateSample* samples, int count) {
  if (recordsArmSamples()) return;
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
  arm_channels_.reset();
  for (AutoScale& scale : scales_) scale.reset();
  if (!isFrozen()) redrawNow();
}

void PlotsWidget::setExternalTorqueMap(std::unique_ptr<ExternalTorqueMap> map) { map_ = std::move(map); }

bool PlotsWidget::isSignalVisible(Signal signal) const {
  const auto s = static_cast<std::size_t>(signal);
  return offered_[s] && signal_on_[s];
}

bool PlotsWidget::channelVisible(int channel) const {
  const Signal signal = signalOfChannel(channel);
  const int joint = jointOfChannel(channel);
  if (!isSignalVisible(signal)) return false;
  if (!isJointSignal(signal)) return joint < componentCount(signal);
  return joint < joint_count_ && joint_on_[static_cast<std::size_t>(joint)];
}

std::vector<int> PlotsWidget::visibleChannels() const {
  std::vector<int> channels;
  for (int c = 0; c < kChannelCount; ++c)
    if (channelVisible(c)) channels.push_back(c);
  return channels;
}

std::vector<int> PlotsWidget::allChannels() const {
  std::vector<int> channels;
  for (int c = 0; c < kChannelCount; ++c) {
    const Signal signal = signalOfChannel(c);
    const int limit = isJointSignal(signal) ? joint_count_ : componentCount(signal);
    if (offered_[static_cast<std::size_t>(signal)] && jointOfChannel(c) < limit) channels.push_back(c);
  }
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
  for (int q = 0; q < kAllQuantityCount; ++q)
    if (isChartShown(static_cast<Quantity>(q))) drawQuantity(static_cast<Quantity>(q), source, range, x0, x1);
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
  if (scope == ExportScope::kWholeBuffer)
    return writeCsv(buffer_, {0, buffer_.size()}, allChannels(), setup_.joint_prefix, path, error);
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
  return writeCsv(*frozen_, frozen_->window(x1 - window_seconds_, x1), channels, setup_.joint_prefix, path, error);
}

}  // namespace rci::ui::plots
