// SPDX-License-Identifier: Apache-2.0
// PlotsWidget: the live plot area -- stacked charts over a 62 s recording ring, joint and signal
// choosers, time window, freeze/resume, CSV export; fed by addSamples() (an xMate's state samples) or
// addArmSamples() (a KUKA's), redrawn on a 30 Hz timer. configure() picks the signals the arm offers.
#pragma once

#include <QList>
#include <QPointF>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <vector>

#include "client/state_sample.h"
#include "arm/arm.h"
#include "plots/arm_channels.h"
#include "plots/auto_scale.h"
#include "plots/decimation.h"
#include "plots/external_torque.h"
#include "plots/plot_buffer.h"
#include "plots/plot_canvas.h"
#include "plots/plot_setup.h"

class QCheckBox;
class QHBoxLayout;
class QResizeEvent;
class QLabel;
class QPushButton;
class QSpinBox;
class QSplitter;

namespace rci::ui::plots {

class PlotsWidget : public QWidget {
  Q_OBJECT
 public:
  static constexpr double kBufferSeconds = 62;  // 60 s window + margin
  static constexpr double kSampleRateHz = 1000;  // the xMate's; configure() sizes the ring for another
  static constexpr int kMinWindowSeconds = 2;
  static constexpr int kMaxWindowSeconds = 60;
  static constexpr int kRedrawIntervalMs = 33;  // ~30 Hz
  // Drawn lines stay within this many pixels of every min/max point (simplifyWithin).
  static constexpr double kToleranceInPixels = 0.5;

  enum class ExportScope { kWholeBuffer, kFrozenView };

  // Starts with the xMate's setup (xmateSetup()).
  explicit PlotsWidget(QWidget* parent = nullptr);
  ~PlotsWidget() override;

  // Every member function: GUI thread only. The add* functions are real-time safe (no allocation).

  // Switches to the signals, joints and sample rate of setup: the choosers offer only its signals,
  // charts without any are hidden, the ring is re-sized (and emptied), a frozen view is resumed.
  // Nothing changes when setup is the current one.
  void configure(const PlotSetup& setup);
  const PlotSetup& setup() const { return setup_; }

  // Records an xMate's state samples (oldest first), when the setup's source is state samples.
  // External torques are mapped with the model set below (0 without).
  void addSamples(const xmate::client::StateSample* samples, int count);
  // Records arm samples (oldest first), when the setup's source is arm samples; extras (sensor wrench,
  // late answers) are this display tick's and held over the batch.
  void addArmSamples(const xmate::arm::ArmSample* samples, int count, const ArmExtras& extras);
  bool recordsArmSamples() const { return setup_.source == PlotSetup::Source::kArmSamples; }
  // Forgets every sample (a new session restarts the clock).
  void clear();
  // The arm's model for tau_ext = J^T F (nullptr: no mapping, external torques shown as 0).
  void setExternalTorqueMap(std::unique_ptr<ExternalTorqueMap> map);
  ExternalTorqueMap* externalTorqueMap() { return map_.get(); }
  // 6 or 7: joint 7 is not offered on 6-axis arms.
  void setJointCount(int joints);
  int jointCount() const { return joint_count_; }

  void setJointVisible(int joint, bool visible);
  void setSignalVisible(Signal signal, bool visible);
  bool isSignalVisible(Signal signal) const;  // offered and ticked
  // The chart is part of the view (its signals are offered; an extra chart: and one is ticked).
  bool isChartShown(Quantity quantity) const;
  void setWindowSeconds(int seconds);
  void setFrozen(bool frozen);
  bool isFrozen() const { return frozen_ != nullptr; }

  // The timer's redraw: skipped while hidden or frozen.
  void redraw();
  // Draws now from the live buffer, or from the frozen snapshot when frozen.
  void redrawNow();

  // kWholeBuffer: every sample held, every offered signal of the arm's joints. kFrozenView: the frozen
  // window, the visible series. Returns false with a message (nothing to export, not frozen, I/O).
  bool exportCsv(const QString& path, ExportScope scope, QString* error) const;

  const PlotBuffer& buffer() const { return buffer_; }
  PlotCanvas& canvas(Quantity quantity) { return *canvases_[static_cast<std::size_t>(quantity)]; }
  int visibleSeriesCount() const;

 signals:
  void frozenChanged(bool frozen);

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  void buildUi();
  QWidget* buildJointChooser();
  QWidget* buildSignalChooser();
  QWidget* buildViewControls();
  void declareSeries();
  void applySetup();
  void updateCharts(bool relayout = false);
  void applyVisibility();
  bool channelVisible(int channel) const;
  std::vector<int> visibleChannels() const;
  std::vector<int> allChannels() const;
  void drawQuantity(Quantity quantity, const PlotBuffer& source, IndexRange range, double x0, double x1);
  void updateStatus();
  void updateFreezeControls();
  // The view controls (window, freeze, export, status) beside the choosers where the width allows,
  // else on a second row: the strip never forces the dock wider than the screen.
  void placeViewControls();
  void askExport(ExportScope scope);

  PlotSetup setup_;
  std::array<bool, kSignalCount> offered_{};
  PlotBuffer buffer_;
  std::unique_ptr<PlotBuffer> frozen_;  // snapshot taken at freeze time
  std::unique_ptr<ExternalTorqueMap> map_;
  ArmChannels arm_channels_;
  ChannelValues scratch_values_{};
  std::array<std::unique_ptr<PlotCanvas>, kAllQuantityCount> canvases_;
  std::array<AutoScale, kAllQuantityCount> scales_;
  MinMaxDecimator decimator_;
  std::array<QList<QPointF>, kChannelCount> points_;  // this frame's points per series
  std::array<bool, kJointCount> joint_on_{};
  std::array<bool, kSignalCount> signal_on_{};
  int joint_count_ = kJointCount;
  int window_seconds_ = 10;

  std::array<QCheckBox*, kJointCount> joint_boxes_{};
  std::array<QCheckBox*, kSignalCount> signal_boxes_{};
  QLabel* joints_caption_ = nullptr;
  QWidget* choosers_[2] = {nullptr, nullptr};  // joint and signal choosers
  QWidget* view_box_ = nullptr;                // view controls + status
  QHBoxLayout* first_row_ = nullptr;
  QHBoxLayout* second_row_ = nullptr;
  bool two_rows_ = false;
  QSplitter* splitter_ = nullptr;
  QSpinBox* window_box_ = nullptr;
  QPushButton* freeze_button_ = nullptr;
  QPushButton* export_button_ = nullptr;
  QLabel* status_ = nullptr;
  QTimer timer_;
};

// Series colour of joint j (0-based), shared by the chooser and the charts.
QColor jointColour(int joint);
// Series colour of a non-joint signal's component: x red, y green, z blue; a single value dark grey.
QColor componentColour(Signal signal, int component);
// The channels of the signals offered, ascending (signal by signal: the ring's and the CSV's column order).
// Any thread.
std::vector<int> keptChannels(const PlotSetup& setup);

}  // namespace rci::ui::plots
