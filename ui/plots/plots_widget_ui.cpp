// SPDX-License-Identifier: Apache-2.0
// PlotsWidget (plots_widget.h), controls: the charts' layout and the one-row control strip (joint and
// signal toggles, time window, freeze/resume, the export menu, the status line).
#include <QCheckBox>
#include <QFileDialog>
#include <QFontMetrics>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

#include <algorithm>

#include "plots/chart_canvas.h"
#include "plots/plots_widget.h"

namespace rci::ui::plots {

QColor jointColour(int joint) {
  static const std::array<QColor, kJointCount> colours{
      QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e), QColor(0x2c, 0xa0, 0x2c), QColor(0xd6, 0x27, 0x28),
      QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b), QColor(0xe3, 0x77, 0xc2)};
  return colours[static_cast<std::size_t>(joint % kJointCount)];
}

namespace {

Qt::PenStyle penStyle(Signal signal) {
  const QString label = signalLabel(signal);
  if (label == QLatin1String("commanded")) return Qt::DashLine;
  if (label == QLatin1String("external")) return Qt::DotLine;
  return Qt::SolidLine;
}

QIcon lineSample(Qt::PenStyle style) {
  QPixmap pixmap(24, 12);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  QPen pen(QColor(60, 60, 60));
  pen.setWidthF(1.6);
  pen.setStyle(style);
  painter.setPen(pen);
  painter.drawLine(1, 6, 23, 6);
  return QIcon(pixmap);
}

// Short axis titles with units: the charts are small, the joint/signal chooser names them in full.
QString axisTitle(Quantity quantity) {
  switch (quantity) {
    case Quantity::kPosition: return QStringLiteral("q [rad]");
    case Quantity::kVelocity: return QStringLiteral("dq [rad/s]");
    default: return QStringLiteral("τ [Nm]");
  }
}

// The short name of a signal in the control strip.
QString signalShortName(Signal signal) {
  switch (signal) {
    case Signal::kPositionMeasured: return QStringLiteral("q");
    case Signal::kPositionCommanded: return QStringLiteral("q cmd");
    case Signal::kVelocityMeasured: return QStringLiteral("dq");
    case Signal::kTorqueMeasured: return QStringLiteral("τ");
    case Signal::kTorqueCommanded: return QStringLiteral("τ cmd");
    default: return QStringLiteral("τ ext");
  }
}

// A joint toggle: its check indicator is a small square filled with the joint's colour when on.
QString jointCheckStyle(const QColor& colour) {
  return QStringLiteral("QCheckBox { spacing: 3px; }"
                        "QCheckBox::indicator { width: 11px; height: 11px; border: 1px solid %1;"
                        " border-radius: 2px; background: palette(base); }"
                        "QCheckBox::indicator:checked { background: %2; }"
                        "QCheckBox::indicator:disabled { border-color: palette(mid); background: palette(window); }")
      .arg(colour.darker(130).name(), colour.name());
}

QFrame* separator(QWidget* parent) {
  auto* line = new QFrame(parent);
  line->setFrameShape(QFrame::VLine);
  line->setFrameShadow(QFrame::Sunken);
  return line;
}

QLabel* caption(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  QPalette palette = label->palette();  // a softer text colour than the controls it names
  QColor colour = palette.color(QPalette::WindowText);
  colour.setAlpha(170);
  palette.setColor(QPalette::WindowText, colour);
  label->setPalette(palette);
  return label;
}

QHBoxLayout* stripLayout(QWidget* owner) {
  auto* row = new QHBoxLayout(owner);
  row->setContentsMargins(0, 0, 0, 0);
  row->setSpacing(6);
  return row;
}

}  // namespace

void PlotsWidget::buildUi() {
  auto* controls = new QHBoxLayout;
  controls->setSpacing(8);
  controls->addWidget(buildJointChooser());
  controls->addWidget(separator(this));
  controls->addWidget(buildSignalChooser());
  controls->addWidget(separator(this));
  controls->addWidget(buildViewControls());
  status_ = new QLabel(this);
  // Right-aligned in the room left; on two lines where the window is narrow, rather than widening the strip.
  status_->setWordWrap(true);
  status_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  status_->setToolTip(tr("Session time of the newest sample shown (the right edge of the charts, 0 s on the "
                          "time axis), and the recorded time held in memory (the most recent %1 s are kept)")
                           .arg(kMaxWindowSeconds));
  controls->addWidget(status_, 1);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->setChildrenCollapsible(false);
  splitter->setHandleWidth(4);
  for (int q = 0; q < kQuantityCount; ++q) {
    auto canvas = std::make_unique<ChartCanvas>(splitter);
    const auto quantity = static_cast<Quantity>(q);
    // The three charts share the time axis: only the bottom one carries its labels and title.
    const bool bottom = q == kQuantityCount - 1;
    canvas->setXLabelsVisible(bottom);
    canvas->setAxisTitles(bottom ? tr("Time [s], 0 = newest sample") : QString(), axisTitle(quantity));
    canvas->widget()->setToolTip(tr("%1 (%2) of the joints ticked under Joints; line style as under Signals")
                                     .arg(quantityTitle(quantity), quantityUnit(quantity)));
    splitter->addWidget(canvas->widget());
    canvases_[static_cast<std::size_t>(q)] = std::move(canvas);
  }
  // Space is shared in proportion to the minimum heights, so the bottom chart -- which also holds the
  // time labels and title -- gets a plot area about as tall as the others.
  QList<int> sizes;
  for (const auto& canvas : canvases_) sizes << canvas->widget()->minimumHeight();
  splitter->setSizes(sizes);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 4, 6, 4);
  layout->setSpacing(4);
  layout->addLayout(controls);
  layout->addWidget(splitter, 1);
}

QWidget* PlotsWidget::buildJointChooser() {
  auto* strip = new QWidget(this);
  QHBoxLayout* row = stripLayout(strip);
  row->addWidget(caption(tr("Joints"), strip));
  for (int j = 0; j < kJointCount; ++j) {
    auto* check = new QCheckBox(QStringLiteral("J%1").arg(j + 1), strip);
    check->setStyleSheet(jointCheckStyle(jointColour(j)));
    check->setChecked(joint_on_[static_cast<std::size_t>(j)]);
    check->setToolTip(tr("Show joint %1 in every chart (its lines are drawn in this colour)").arg(j + 1));
    connect(check, &QCheckBox::toggled, this, [this, j](bool on) { setJointVisible(j, on); });
    row->addWidget(check);
    joint_boxes_[static_cast<std::size_t>(j)] = check;
  }
  return strip;
}

QWidget* PlotsWidget::buildSignalChooser() {
  auto* strip = new QWidget(this);
  QHBoxLayout* row = stripLayout(strip);
  row->addWidget(caption(tr("Signals"), strip));
  for (int s = 0; s < kSignalCount; ++s) {
    const auto signal = static_cast<Signal>(s);
    auto* check = new QCheckBox(signalShortName(signal), strip);
    check->setIcon(lineSample(penStyle(signal)));
    check->setIconSize(QSize(24, 12));
    check->setChecked(signal_on_[static_cast<std::size_t>(s)]);
    check->setToolTip(tr("%1 %2 (%3), drawn %4")
                          .arg(quantityTitle(quantityOf(signal)), signalLabel(signal),
                               quantityUnit(quantityOf(signal)),
                               penStyle(signal) == Qt::SolidLine  ? tr("solid")
                               : penStyle(signal) == Qt::DashLine ? tr("dashed")
                                                                  : tr("dotted")));
    connect(check, &QCheckBox::toggled, this, [this, signal](bool on) { setSignalVisible(signal, on); });
    row->addWidget(check);
    signal_boxes_[static_cast<std::size_t>(s)] = check;
  }
  signal_boxes_[static_cast<int>(Signal::kTorqueExternal)]->setToolTip(
      tr("External joint torques (Nm): the external wrench at the TCP mapped with J(q)^T, drawn dotted"));
  return strip;
}

QWidget* PlotsWidget::buildViewControls() {
  auto* strip = new QWidget(this);
  QHBoxLayout* row = stripLayout(strip);
  row->addWidget(caption(tr("Window"), strip));
  window_box_ = new QSpinBox(strip);
  window_box_->setRange(kMinWindowSeconds, kMaxWindowSeconds);
  window_box_->setValue(window_seconds_);
  window_box_->setSuffix(tr(" s"));
  window_box_->setToolTip(tr("Span of the time axis, %1 to %2 seconds").arg(kMinWindowSeconds).arg(kMaxWindowSeconds));
  connect(window_box_, &QSpinBox::valueChanged, this, &PlotsWidget::setWindowSeconds);
  row->addWidget(window_box_);

  freeze_button_ = new QPushButton(tr("Freeze"), strip);
  freeze_button_->setCheckable(true);
  freeze_button_->setToolTip(tr("Stop scrolling to inspect the plots; recording continues in the background"));
  // Wide enough for "Resume" too, so the strip does not shift when the text changes.
  const QFontMetrics metrics(freeze_button_->font());
  freeze_button_->setMinimumWidth(
      std::max(metrics.horizontalAdvance(tr("Freeze")), metrics.horizontalAdvance(tr("Resume"))) + 24);
  connect(freeze_button_, &QPushButton::toggled, this, &PlotsWidget::setFrozen);
  row->addWidget(freeze_button_);

  export_button_ = new QPushButton(tr("Export CSV…"), strip);
  export_button_->setToolTip(tr("Save recorded samples as CSV (time in s, one column per joint and signal, units in the header)"));
  auto* menu = new QMenu(export_button_);
  menu->addAction(tr("Whole buffer (all signals)…"), this, [this] { askExport(ExportScope::kWholeBuffer); });
  QAction* view_action =
      menu->addAction(tr("Frozen view (shown series)…"), this, [this] { askExport(ExportScope::kFrozenView); });
  connect(menu, &QMenu::aboutToShow, this, [this, view_action] { view_action->setEnabled(isFrozen()); });
  export_button_->setMenu(menu);
  row->addWidget(export_button_);
  return strip;
}

void PlotsWidget::declareSeries() {
  for (int c = 0; c < kChannelCount; ++c) {
    const Signal signal = signalOfChannel(c);
    const int joint = jointOfChannel(c);
    canvas(quantityOf(signal))
        .addSeries(c, QStringLiteral("J%1 %2").arg(joint + 1).arg(signalLabel(signal)), jointColour(joint),
                   penStyle(signal));
  }
}

void PlotsWidget::setJointCount(int joints) {
  joint_count_ = std::clamp(joints, 1, kJointCount);
  for (int j = 0; j < kJointCount; ++j) joint_boxes_[static_cast<std::size_t>(j)]->setEnabled(j < joint_count_);
  applyVisibility();
  redrawNow();
}

void PlotsWidget::setJointVisible(int joint, bool visible) {
  if (joint < 0 || joint >= kJointCount) return;
  joint_on_[static_cast<std::size_t>(joint)] = visible;
  QSignalBlocker block(joint_boxes_[static_cast<std::size_t>(joint)]);
  joint_boxes_[static_cast<std::size_t>(joint)]->setChecked(visible);
  applyVisibility();
  redrawNow();
}

void PlotsWidget::setSignalVisible(Signal signal, bool visible) {
  const auto s = static_cast<std::size_t>(signal);
  signal_on_[s] = visible;
  QSignalBlocker block(signal_boxes_[s]);
  signal_boxes_[s]->setChecked(visible);
  applyVisibility();
  redrawNow();
}

void PlotsWidget::setWindowSeconds(int seconds) {
  window_seconds_ = std::clamp(seconds, kMinWindowSeconds, kMaxWindowSeconds);
  QSignalBlocker block(window_box_);
  window_box_->setValue(window_seconds_);
  for (AutoScale& scale : scales_) scale.reset();
  redrawNow();
}

void PlotsWidget::updateFreezeControls() {
  QSignalBlocker block(freeze_button_);
  freeze_button_->setChecked(isFrozen());
  freeze_button_->setText(isFrozen() ? tr("Resume") : tr("Freeze"));
}

void PlotsWidget::updateStatus() {
  const double held = buffer_.size() > 1 ? buffer_.newestTime() - buffer_.oldestTime() : 0.0;
  const PlotBuffer& shown = frozen_ ? *frozen_ : buffer_;
  const double newest = shown.empty() ? 0.0 : shown.newestTime();
  const QString text = tr("%1 at t = %2 s · %3 s recorded")
                           .arg(isFrozen() ? tr("Frozen") : tr("Live"))
                           .arg(newest, 0, 'f', 1)
                           .arg(held, 0, 'f', 1);
  if (status_->text() != text) status_->setText(text);
}

void PlotsWidget::askExport(ExportScope scope) {
  const QString path = QFileDialog::getSaveFileName(this, tr("Export plots to CSV"), QStringLiteral("rci_plots.csv"),
                                                    tr("CSV files (*.csv);;All files (*)"));
  if (path.isEmpty()) return;
  QString error;
  if (!exportCsv(path, scope, &error)) QMessageBox::warning(this, tr("Export CSV"), error);
}

}  // namespace rci::ui::plots
