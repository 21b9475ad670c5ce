// SPDX-License-Identifier: Apache-2.0
// PlotsWidget (plots_widget.h), controls: the charts' layout and the one-row control strip (joint and
// signal toggles, time window, freeze/resume, the export menu, the status line).
#include <QCheckBox>
#include <QFileDialog>
#include <QFontMetrics>
#include <QFrame>
#include <QHBoxLayout>
#include <QResizeEvent>
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

QColor componentColour(Signal signal, int component) {
  if (componentCount(signal) == 1) return QColor(0x44, 0x44, 0x44);
  static const std::array<QColor, 3> xyz{QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c), QColor(0x1f, 0x5f, 0xd4)};
  return xyz[static_cast<std::size_t>(component % 3)];
}

namespace {

Qt::PenStyle penStyle(Signal signal) {
  switch (signal) {
    case Signal::kPositionCommanded:
    case Signal::kTorqueCommanded:
    case Signal::kAxisSetPoint:
    case Signal::kSensorTorque:
    case Signal::kTcpSetPoint: return Qt::DashLine;
    case Signal::kTorqueExternal: return Qt::DotLine;
    default: return Qt::SolidLine;
  }
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
    case Quantity::kMotorCurrent: return QStringLiteral("I [A]");
    case Quantity::kForce: return QStringLiteral("F,T [N,Nm]");  // both ticked
    case Quantity::kDelay: return QStringLiteral("late");
    case Quantity::kTcp: return QStringLiteral("TCP [m]");
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
    case Signal::kTorqueExternal: return QStringLiteral("τ ext");
    case Signal::kAxisActual: return QStringLiteral("q");
    case Signal::kAxisSetPoint: return QStringLiteral("q set");
    case Signal::kAxisVelocity: return QStringLiteral("dq");
    case Signal::kGearTorque: return QStringLiteral("τ gear");
    case Signal::kMotorCurrent: return QStringLiteral("I motor");
    case Signal::kSensorForce: return QStringLiteral("F sensor");
    case Signal::kSensorTorque: return QStringLiteral("T sensor");
    case Signal::kTcpActual: return QStringLiteral("TCP");
    case Signal::kTcpSetPoint: return QStringLiteral("TCP set");
    default: return QStringLiteral("late");
  }
}

QString styleWord(Qt::PenStyle style) {
  return style == Qt::SolidLine ? QObject::tr("solid") : style == Qt::DashLine ? QObject::tr("dashed") : QObject::tr("dotted");
}

// What a signal's check box says when the pointer rests on it.
QString signalToolTip(Signal signal) {
  const QString drawn = styleWord(penStyle(signal));
  switch (signal) {
    case Signal::kTorqueExternal:
      return QObject::tr("External joint torques (Nm): the external wrench at the TCP mapped with J(q)^T, drawn dotted");
    case Signal::kAxisActual:
      return QObject::tr("Actual axis positions (rad), as the robot measures them, drawn %1").arg(drawn);
    case Signal::kAxisSetPoint:
      return QObject::tr("Axis set-points (rad): where the robot controller is taking the axes, drawn %1").arg(drawn);
    case Signal::kAxisVelocity:
      return QObject::tr("Axis velocities (rad/s), from consecutive actual positions, drawn %1").arg(drawn);
    case Signal::kGearTorque:
      return QObject::tr("Gear torques (Nm) the robot reports for its axes, drawn %1").arg(drawn);
    case Signal::kMotorCurrent:
      return QObject::tr("Motor currents (A) of the axes, in their own chart, drawn %1").arg(drawn);
    case Signal::kSensorForce:
      return QObject::tr("Force the F/T sensor measures (N), in its own frame: Fx red, Fy green, Fz blue, drawn %1. "
                         "Gaps: no recent reading from the sensor").arg(drawn);
    case Signal::kSensorTorque:
      return QObject::tr("Torque the F/T sensor measures (Nm), in its own frame: Tx red, Ty green, Tz blue, drawn %1")
          .arg(drawn);
    case Signal::kTcpActual:
      return QObject::tr("Position of the TCP (m) in the robot's base frame, as the robot reports it: X red, Y green, "
                         "Z blue, drawn %1").arg(drawn);
    case Signal::kTcpSetPoint:
      return QObject::tr("Where the robot controller takes the TCP (m, base frame): X red, Y green, Z blue, drawn %1")
          .arg(drawn);
    case Signal::kLateAnswers:
      return QObject::tr("Late answers the robot has counted (its Delay): it grows when this PC answers a cycle too "
                         "late, and RSI stops when it reaches the limit of the RSI context");
    default:
      return QObject::tr("%1 %2 (%3), drawn %4")
          .arg(quantityTitle(quantityOf(signal)), signalLabel(signal), quantityUnit(quantityOf(signal)), drawn);
  }
}

// What a chart says when the pointer rests on it.
QString chartToolTip(Quantity quantity, const QString& joints_caption) {
  switch (quantity) {
    case Quantity::kForce:
      return QObject::tr("Force sensor: force (N, solid) and torque (Nm, dashed) in the sensor's frame; x red, "
                         "y green, z blue");
    case Quantity::kDelay:
      return QObject::tr("Late answers the robot has counted in this RSI session (its Delay)");
    case Quantity::kTcp:
      return QObject::tr("TCP position (m) in the base frame: actual solid, set-point dashed; X red, Y green, Z blue");
    default:
      return QObject::tr("%1 (%2) of the %3 ticked under %4; line style as under Signals")
          .arg(quantityTitle(quantity), quantityUnit(quantity), joints_caption.toLower(), joints_caption);
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
  first_row_ = new QHBoxLayout;
  first_row_->setSpacing(8);
  choosers_[0] = buildJointChooser();
  choosers_[1] = buildSignalChooser();
  first_row_->addWidget(choosers_[0]);
  first_row_->addWidget(separator(this));
  first_row_->addWidget(choosers_[1]);
  first_row_->addWidget(separator(this));
  view_box_ = new QWidget(this);
  auto* view_row = new QHBoxLayout(view_box_);
  view_row->setContentsMargins(0, 0, 0, 0);
  view_row->setSpacing(8);
  view_row->addWidget(buildViewControls());
  status_ = new QLabel(view_box_);
  // Right-aligned in the room left; on two lines where the window is narrow, rather than widening the strip.
  status_->setWordWrap(true);
  status_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  status_->setToolTip(tr("Session time of the newest sample shown (the right edge of the charts, 0 s on the "
                          "time axis), and the recorded time held in memory (the most recent %1 s are kept)")
                           .arg(kMaxWindowSeconds));
  view_row->addWidget(status_, 1);
  first_row_->addWidget(view_box_, 1);
  second_row_ = new QHBoxLayout;

  splitter_ = new QSplitter(Qt::Vertical, this);
  splitter_->setChildrenCollapsible(false);
  splitter_->setHandleWidth(4);
  for (int q = 0; q < kAllQuantityCount; ++q) {
    auto canvas = std::make_unique<ChartCanvas>(splitter_);
    splitter_->addWidget(canvas->widget());
    canvases_[static_cast<std::size_t>(q)] = std::move(canvas);
  }

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 4, 6, 4);
  layout->setSpacing(4);
  layout->addLayout(first_row_);
  layout->addLayout(second_row_);
  layout->addWidget(splitter_, 1);
}

void PlotsWidget::placeViewControls() {
  if (!view_box_) return;
  // The width the widget gets: its scroll area's viewport (or its dock) -- not its own width, which
  // a scroll area stretches to the strip's minimum.
  const int available = parentWidget() ? parentWidget()->width() : width();
  const int one_row = choosers_[0]->sizeHint().width() + choosers_[1]->sizeHint().width() +
                      view_box_->minimumSizeHint().width() + 60;  // separators, spacing, margins
  const bool two = one_row > available;
  if (two == two_rows_) return;
  two_rows_ = two;
  (two ? first_row_ : second_row_)->removeWidget(view_box_);
  if (two) {
    second_row_->addWidget(view_box_, 1);
    first_row_->addStretch(1);  // the choosers keep their natural width, left-aligned
  } else {
    delete first_row_->takeAt(first_row_->count() - 1);  // that stretch
    first_row_->addWidget(view_box_, 1);
  }
}

void PlotsWidget::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  placeViewControls();
}

// The charts of the setup's signals, the bottom one shown carrying the time axis; the splitter's
// space is shared out again when charts came or went (or relayout).
void PlotsWidget::updateCharts(bool relayout) {
  int bottom = -1;
  for (int q = 0; q < kAllQuantityCount; ++q)
    if (isChartShown(static_cast<Quantity>(q))) bottom = q;
  bool changed = false;
  for (int q = 0; q < kAllQuantityCount; ++q) {
    const auto quantity = static_cast<Quantity>(q);
    auto* chart = static_cast<ChartCanvas*>(canvases_[static_cast<std::size_t>(q)].get());
    // The charts share the time axis: only the bottom one carries its labels and title.
    chart->setXLabelsVisible(q == bottom);
    QString title = axisTitle(quantity);
    if (quantity == Quantity::kForce && !isSignalVisible(Signal::kSensorTorque)) title = QStringLiteral("F [N]");
    if (quantity == Quantity::kForce && !isSignalVisible(Signal::kSensorForce)) title = QStringLiteral("T [Nm]");
    chart->setAxisTitles(q == bottom ? tr("Time [s], 0 = newest sample") : QString(), title);
    chart->widget()->setToolTip(chartToolTip(quantity, setup_.joints_caption));
    const bool shown = isChartShown(quantity);
    if (chart->widget()->isVisibleTo(this) != shown) changed = true;
    chart->widget()->setVisible(shown);
  }
  if (!changed && !relayout) return;
  // Space is shared in proportion to the minimum heights, so the bottom chart -- which also holds the
  // time labels and title -- gets a plot area about as tall as the others.
  QList<int> sizes;
  for (const auto& canvas : canvases_)
    sizes << (canvas->widget()->isVisibleTo(this) ? canvas->widget()->minimumHeight() : 0);
  splitter_->setSizes(sizes);
}

bool PlotsWidget::isChartShown(Quantity quantity) const {
  bool offered = false, ticked = false;
  for (Signal signal : setup_.offered) {
    if (quantityOf(signal) != quantity) continue;
    offered = true;
    ticked = ticked || signal_on_[static_cast<std::size_t>(signal)];
  }
  return offered && (ticked || !quantityCollapses(quantity));
}

// Shows the choosers' boxes and the charts of the setup's signals and joints, named as the setup says.
void PlotsWidget::applySetup() {
  joints_caption_->setText(setup_.joints_caption);
  for (int j = 0; j < kJointCount; ++j) {
    QCheckBox* box = joint_boxes_[static_cast<std::size_t>(j)];
    box->setText(setup_.joint_prefix + QString::number(j + 1));
    box->setToolTip(tr("Show %1 in every chart (its lines are drawn in this colour)").arg(setup_.joint_title.arg(j + 1)));
    box->setVisible(j < setup_.joints);
    box->setEnabled(j < joint_count_);
  }
  for (int s = 0; s < kSignalCount; ++s) {
    QCheckBox* box = signal_boxes_[static_cast<std::size_t>(s)];
    QSignalBlocker block(box);
    box->setChecked(signal_on_[static_cast<std::size_t>(s)]);
    box->setVisible(offered_[static_cast<std::size_t>(s)]);
  }
  updateCharts(true);
  applyVisibility();
  placeViewControls();
}

QWidget* PlotsWidget::buildJointChooser() {
  auto* strip = new QWidget(this);
  QHBoxLayout* row = stripLayout(strip);
  joints_caption_ = caption(tr("Joints"), strip);
  row->addWidget(joints_caption_);
  for (int j = 0; j < kJointCount; ++j) {
    auto* check = new QCheckBox(QStringLiteral("J%1").arg(j + 1), strip);
    check->setStyleSheet(jointCheckStyle(jointColour(j)));
    check->setChecked(joint_on_[static_cast<std::size_t>(j)]);
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
    check->setToolTip(signalToolTip(signal));
    connect(check, &QCheckBox::toggled, this, [this, signal](bool on) { setSignalVisible(signal, on); });
    row->addWidget(check);
    signal_boxes_[static_cast<std::size_t>(s)] = check;
  }
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
    const bool per_joint = isJointSignal(signal);
    canvas(quantityOf(signal))
        .addSeries(c,
                   per_joint ? QStringLiteral("J%1 %2").arg(joint + 1).arg(signalLabel(signal))
                             : QStringLiteral("%1 %2").arg(componentName(signal, joint), signalLabel(signal)),
                   per_joint ? jointColour(joint) : componentColour(signal, joint), penStyle(signal));
  }
}

void PlotsWidget::setJointCount(int joints) {
  joint_count_ = std::clamp(joints, 1, std::min(kJointCount, setup_.joints));
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
  updateCharts();
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
