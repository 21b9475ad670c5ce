// PlotsWidget (plots_widget.h), controls: the charts' layout, joint and signal choosers, time window,
// freeze/resume, the export menu and the status line.
#include <QCheckBox>
#include <QFileDialog>
#include <QGridLayout>
#include <QGroupBox>
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

QIcon swatch(const QColor& colour) {
  QPixmap pixmap(12, 12);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  painter.setPen(colour.darker(130));
  painter.setBrush(colour);
  painter.drawRect(0, 0, 11, 11);
  return QIcon(pixmap);
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

}  // namespace

void PlotsWidget::buildUi() {
  auto* controls = new QHBoxLayout;
  controls->setSpacing(8);
  controls->addWidget(buildJointChooser());
  controls->addWidget(buildSignalChooser());
  controls->addWidget(buildViewControls(), 1);

  auto* splitter = new QSplitter(Qt::Vertical, this);
  splitter->setChildrenCollapsible(false);
  for (int q = 0; q < kQuantityCount; ++q) {
    auto canvas = std::make_unique<ChartCanvas>(splitter);
    const auto quantity = static_cast<Quantity>(q);
    // One time-axis title, under the bottom chart: the three charts share the time axis.
    const bool bottom = q == kQuantityCount - 1;
    canvas->setAxisTitles(bottom ? tr("Time (s), 0 = newest sample") : QString(),
                          QStringLiteral("%1 (%2)").arg(quantityTitle(quantity), quantityUnit(quantity)));
    splitter->addWidget(canvas->widget());
    canvases_[static_cast<std::size_t>(q)] = std::move(canvas);
  }

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(6, 6, 6, 6);
  layout->setSpacing(6);
  layout->addLayout(controls);
  layout->addWidget(splitter, 1);
}

QWidget* PlotsWidget::buildJointChooser() {
  auto* box = new QGroupBox(tr("Joints"), this);
  auto* grid = new QGridLayout(box);
  grid->setHorizontalSpacing(10);
  for (int j = 0; j < kJointCount; ++j) {
    auto* check = new QCheckBox(QStringLiteral("J%1").arg(j + 1), box);
    check->setIcon(swatch(jointColour(j)));
    check->setChecked(joint_on_[static_cast<std::size_t>(j)]);
    check->setToolTip(tr("Show joint %1 in every chart").arg(j + 1));
    connect(check, &QCheckBox::toggled, this, [this, j](bool on) { setJointVisible(j, on); });
    grid->addWidget(check, j / 4, j % 4);
    joint_boxes_[static_cast<std::size_t>(j)] = check;
  }
  return box;
}

QWidget* PlotsWidget::buildSignalChooser() {
  auto* box = new QGroupBox(tr("Signals"), this);
  auto* grid = new QGridLayout(box);
  grid->setHorizontalSpacing(10);
  const std::array<QString, kQuantityCount> rows{tr("Position:"), tr("Velocity:"), tr("Torque:")};
  std::array<int, kQuantityCount> next_column{1, 1, 1};
  for (int q = 0; q < kQuantityCount; ++q) grid->addWidget(new QLabel(rows[static_cast<std::size_t>(q)], box), q, 0);
  for (int s = 0; s < kSignalCount; ++s) {
    const auto signal = static_cast<Signal>(s);
    const int row = static_cast<int>(quantityOf(signal));
    auto* check = new QCheckBox(signalLabel(signal), box);
    check->setIcon(lineSample(penStyle(signal)));
    check->setChecked(signal_on_[static_cast<std::size_t>(s)]);
    check->setToolTip(tr("%1 %2 (%3), drawn %4")
                          .arg(quantityTitle(quantityOf(signal)), signalLabel(signal),
                               quantityUnit(quantityOf(signal)),
                               penStyle(signal) == Qt::SolidLine  ? tr("solid")
                               : penStyle(signal) == Qt::DashLine ? tr("dashed")
                                                                  : tr("dotted")));
    connect(check, &QCheckBox::toggled, this, [this, signal](bool on) { setSignalVisible(signal, on); });
    grid->addWidget(check, row, next_column[static_cast<std::size_t>(row)]++);
    signal_boxes_[static_cast<std::size_t>(s)] = check;
  }
  signal_boxes_[static_cast<int>(Signal::kTorqueExternal)]->setToolTip(
      tr("External joint torques (Nm): the external wrench at the TCP mapped with J(q)^T, drawn dotted"));
  return box;
}

QWidget* PlotsWidget::buildViewControls() {
  auto* box = new QGroupBox(tr("View"), this);
  auto* grid = new QGridLayout(box);
  grid->addWidget(new QLabel(tr("Time window:"), box), 0, 0);
  window_box_ = new QSpinBox(box);
  window_box_->setRange(kMinWindowSeconds, kMaxWindowSeconds);
  window_box_->setValue(window_seconds_);
  window_box_->setSuffix(tr(" s"));
  window_box_->setToolTip(tr("Span of the time axis, %1 to %2 seconds").arg(kMinWindowSeconds).arg(kMaxWindowSeconds));
  connect(window_box_, &QSpinBox::valueChanged, this, &PlotsWidget::setWindowSeconds);
  grid->addWidget(window_box_, 0, 1);

  freeze_button_ = new QPushButton(tr("Freeze"), box);
  freeze_button_->setCheckable(true);
  freeze_button_->setToolTip(tr("Stop scrolling to inspect the plots; recording continues in the background"));
  connect(freeze_button_, &QPushButton::toggled, this, &PlotsWidget::setFrozen);
  grid->addWidget(freeze_button_, 1, 0);

  export_button_ = new QPushButton(tr("Export CSV…"), box);
  export_button_->setToolTip(tr("Save recorded samples as CSV (time in s, one column per joint and signal, units in the header)"));
  auto* menu = new QMenu(export_button_);
  menu->addAction(tr("Whole buffer (all signals)…"), this, [this] { askExport(ExportScope::kWholeBuffer); });
  QAction* view_action =
      menu->addAction(tr("Frozen view (shown series)…"), this, [this] { askExport(ExportScope::kFrozenView); });
  connect(menu, &QMenu::aboutToShow, this, [this, view_action] { view_action->setEnabled(isFrozen()); });
  export_button_->setMenu(menu);
  grid->addWidget(export_button_, 1, 1);

  status_ = new QLabel(box);
  status_->setToolTip(tr("Session time of the newest sample shown (the right edge of the charts, 0 s on the "
                          "time axis), and the recorded time held in memory (the most recent %1 s are kept)")
                           .arg(kMaxWindowSeconds));
  grid->addWidget(status_, 2, 0, 1, 2);
  grid->setColumnStretch(2, 1);
  return box;
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
