// SPDX-License-Identifier: Apache-2.0
// Safety panel (safety_panel.h): the live problems in operator words (text/operator_text.h), the
// Recover button, the stop lamps and the 20 error conditions. Laid out to fit a narrow dock: every
// text wraps, nothing needs more than about 340 px.
#include "panels/safety_panel.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

#include "client/error_bits.h"
#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {

namespace {

QLabel* wrapped(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  return label;
}

QString bitTip(int bit) {
  const text::OperatorMessage m = text::errorBit(bit);
  return QStringLiteral("%1\n%2\n%3 %4\n\n(%5)")
      .arg(m.title, m.what, QObject::tr("What to do:"), m.todo, m.detail);
}

}  // namespace

SafetyPanel::SafetyPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("safety"), tr("Safety"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  body()->addWidget(makeActive());
  body()->addWidget(makeStops());
  body()->addWidget(makeConditions());
  showAll(loadValue(QStringLiteral("showAll"), false).toBool());
  sessionClosed();
}

QWidget* SafetyPanel::makeActive() {
  auto* group = new QGroupBox(tr("What is wrong now"), this);
  group->setObjectName(QStringLiteral("safety.active"));
  auto* layout = new QVBoxLayout(group);
  details_ = new QLabel(group);
  details_->setObjectName(QStringLiteral("safety.details"));
  details_->setWordWrap(true);
  details_->setTextFormat(Qt::RichText);
  details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(details_);
  recover_ = new QPushButton(tr("Recover"), group);
  recover_->setObjectName(QStringLiteral("safety.recover"));
  recover_->setToolTip(tr("Clear the errors the robot reports so it can move again. If a collision or leaving the "
                          "safety box switched the motors off, press Power on in the Power panel afterwards."));
  addSendWidget(recover_);
  connect(recover_, &QPushButton::clicked, this, [this] {
    send(tr("recover errors"), [](xmate::Robot& r) { r.automaticErrorRecovery(); });
  });
  auto* row = new QHBoxLayout;
  row->addWidget(recover_);
  row->addStretch(1);
  layout->addLayout(row);
  return group;
}

QWidget* SafetyPanel::makeStops() {
  auto* group = new QGroupBox(tr("Stops"), this);
  auto* grid = new QGridLayout(group);
  estop_ = new Lamp(lampRed(), group);
  estop_->setObjectName(QStringLiteral("safety.estop"));
  estop_->setToolTip(tr("On while the emergency stop is pressed: the motors stay off until it is released"));
  gstop_ = new Lamp(lampAmber(), group);
  gstop_->setObjectName(QStringLiteral("safety.gstop"));
  gstop_->setToolTip(tr("On while the guard stop is active (safety door open): no motion until it is closed"));
  mode_ = wrapped(QString(), group);
  mode_->setObjectName(QStringLiteral("safety.mode"));
  mode_->setToolTip(tr("What the robot is doing, as its controller reports it"));
  grid->addWidget(estop_, 0, 0);
  grid->addWidget(wrapped(tr("Emergency stop"), group), 0, 1);
  grid->addWidget(gstop_, 1, 0);
  grid->addWidget(wrapped(tr("Guard stop (safety door)"), group), 1, 1);
  grid->addWidget(mode_, 2, 0, 1, 2);
  grid->setColumnStretch(1, 1);
  return group;
}

QWidget* SafetyPanel::makeConditions() {
  auto* group = new QGroupBox(tr("All error conditions"), this);
  auto* layout = new QVBoxLayout(group);
  show_all_ = new QToolButton(group);
  show_all_->setObjectName(QStringLiteral("safety.showAll"));
  show_all_->setCheckable(true);
  show_all_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  show_all_->setToolTip(tr("Show or hide the list of everything the robot can report; active ones are red"));
  connect(show_all_, &QToolButton::toggled, this, [this](bool on) {
    showAll(on);
    saveValue(QStringLiteral("showAll"), on);
  });
  layout->addWidget(show_all_);
  conditions_ = new QWidget(group);
  auto* grid = new QGridLayout(conditions_);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setVerticalSpacing(2);
  for (int i = 0; i < text::kErrorBitCount; ++i) {
    auto* lamp = new Lamp(lampRed(), conditions_);
    lamp->setObjectName(QStringLiteral("safety.bit%1").arg(i));
    auto* label = wrapped(text::errorBitTitle(i), conditions_);
    label->setObjectName(QStringLiteral("safety.bitname%1").arg(i));
    const QString tip = bitTip(i);
    lamp->setToolTip(tip);
    label->setToolTip(tip);
    grid->addWidget(lamp, i, 0, Qt::AlignTop);
    grid->addWidget(label, i, 1);
    bit_lamps_[size_t(i)] = lamp;
    bit_labels_[size_t(i)] = label;
  }
  grid->setColumnStretch(1, 1);
  layout->addWidget(conditions_);
  return group;
}

void SafetyPanel::showAll(bool shown) {
  show_all_->setChecked(shown);
  show_all_->setArrowType(shown ? Qt::DownArrow : Qt::RightArrow);
  show_all_->setText(shown ? tr("Hide the list") : tr("Show all %1").arg(text::kErrorBitCount));
  conditions_->setVisible(shown);
}

void SafetyPanel::refresh(const LiveState& live) {
  estop_->setOn(live.safety_stop == 2);
  gstop_->setOn(live.safety_stop == 3);
  if (!live.has_state) return;
  mode_->setText(tr("Robot: %1").arg(text::robotMode(live.state.robot_mode)));
  showBits(xmate::client::errorMask(live.state.errors));
  showProblems();
}

void SafetyPanel::sessionClosed() {
  estop_->setOn(false);
  gstop_->setOn(false);
  mode_->setText(tr("Not connected"));
  showBits(0);
  shown_details_.clear();
  details_->setText(tr("Not connected."));
  details_->setToolTip(QString());
}

// Active errors first, each with what happened and what to do; unchanged text is not set again.
void SafetyPanel::showProblems() {
  const std::vector<text::OperatorMessage> problems = text::activeProblems(text::viewOf(session()));
  QStringList paragraphs, details;
  for (const text::OperatorMessage& m : problems) {
    paragraphs << QStringLiteral("<p style=\"color:#b02020\">%1</p>").arg(m.html());
    if (!m.detail.isEmpty()) details << m.detail;
  }
  const QString html = paragraphs.isEmpty() ? tr("No errors.") : paragraphs.join(QString());
  if (recover_->font().bold() != !problems.empty()) {
    QFont font = recover_->font();
    font.setBold(!problems.empty());
    recover_->setFont(font);
  }
  if (html == shown_details_) return;
  shown_details_ = html;
  details_->setText(html);
  details_->setToolTip(details.isEmpty() ? QString() : tr("As the controller names them: %1").arg(details.join(QStringLiteral(", "))));
}

void SafetyPanel::showBits(uint32_t mask) {
  if (mask == shown_mask_) return;
  shown_mask_ = mask;
  for (int i = 0; i < text::kErrorBitCount; ++i) {
    const bool on = (mask >> i) & 1u;
    bit_lamps_[size_t(i)]->setOn(on);
    QFont font = bit_labels_[size_t(i)]->font();
    font.setBold(on);
    bit_labels_[size_t(i)]->setFont(font);
    bit_labels_[size_t(i)]->setStyleSheet(on ? QStringLiteral("color: #b02020;") : QString());
  }
}

}  // namespace rci::ui
