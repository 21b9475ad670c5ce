// Safety panel: stop states and error bits from the live state, remedies from client/error_bits.
#include "panels/safety_panel.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {

using xmate::client::kErrorBitCount;

SafetyPanel::SafetyPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("safety"), tr("Safety"), parent) {
  auto* stops = new QGroupBox(tr("Safety stops"), this);
  auto* stop_row = new QHBoxLayout(stops);
  estop_ = new Lamp(lampRed(), stops);
  estop_->setObjectName(QStringLiteral("safety.estop"));
  estop_->setToolTip(tr("Emergency stop pressed (getSafetyStopState() = 2): motors off until released"));
  gstop_ = new Lamp(lampAmber(), stops);
  gstop_->setObjectName(QStringLiteral("safety.gstop"));
  gstop_->setToolTip(tr("Guard stop active (getSafetyStopState() = 3): motion stopped until released"));
  mode_ = new QLabel(stops);
  mode_->setObjectName(QStringLiteral("safety.mode"));
  mode_->setToolTip(tr("Robot mode of the newest state"));
  stop_row->addWidget(estop_);
  stop_row->addWidget(new QLabel(tr("ESTOP"), stops));
  stop_row->addSpacing(12);
  stop_row->addWidget(gstop_);
  stop_row->addWidget(new QLabel(tr("GSTOP"), stops));
  stop_row->addStretch(1);
  stop_row->addWidget(mode_);
  body()->addWidget(stops);

  auto* bits = new QGroupBox(tr("Error bits"), this);
  auto* grid = new QGridLayout(bits);
  grid->setVerticalSpacing(2);
  for (int i = 0; i < kErrorBitCount; ++i) {
    auto* lamp = new Lamp(lampRed(), bits);
    lamp->setObjectName(QStringLiteral("safety.bit%1").arg(i));
    auto* label = new QLabel(QStringLiteral("%1  %2").arg(i, 2).arg(QLatin1String(xmate::client::errorBitName(i))), bits);
    label->setObjectName(QStringLiteral("safety.bitname%1").arg(i));
    const QString tip = QStringLiteral("%1\n\nRemedy: %2")
                            .arg(QString::fromUtf8(xmate::client::errorBitMeaning(i)),
                                 QString::fromUtf8(xmate::client::errorBitRemedy(i)));
    lamp->setToolTip(tip);
    label->setToolTip(tip);
    grid->addWidget(lamp, i, 0);
    grid->addWidget(label, i, 1);
    bit_lamps_[i] = lamp;
    bit_labels_[i] = label;
  }
  grid->setColumnStretch(1, 1);
  body()->addWidget(bits);

  auto* active = new QGroupBox(tr("Active errors"), this);
  auto* active_layout = new QVBoxLayout(active);
  details_ = new QLabel(active);
  details_->setObjectName(QStringLiteral("safety.details"));
  details_->setWordWrap(true);
  details_->setTextFormat(Qt::RichText);
  details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  active_layout->addWidget(details_);
  auto* recover = new QPushButton(tr("Recover errors"), active);
  recover->setObjectName(QStringLiteral("safety.recover"));
  recover->setToolTip(tr("Clear the error bits (automaticErrorRecovery); power the motors on again afterwards "
                         "if a collision or the safety box switched them off"));
  addSendWidget(recover);
  connect(recover, &QPushButton::clicked, this, [this] {
    send(tr("recover errors"), [](xmate::Robot& r) { r.automaticErrorRecovery(); });
  });
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(recover);
  active_layout->addLayout(row);
  body()->addWidget(active);
  showErrors(0);
}

void SafetyPanel::refresh(const LiveState& live) {
  estop_->setOn(live.safety_stop == 2);
  gstop_->setOn(live.safety_stop == 3);
  if (!live.has_state) return;
  mode_->setText(tr("Mode: %1").arg(QLatin1String(xmate::client::robotModeName(live.state.robot_mode))));
  showErrors(xmate::client::errorMask(live.state.errors));
}

void SafetyPanel::sessionClosed() {
  estop_->setOn(false);
  gstop_->setOn(false);
  mode_->setText(tr("Not connected"));
  showErrors(0);
}

void SafetyPanel::showErrors(uint32_t mask) {
  if (mask == shown_mask_) return;
  shown_mask_ = mask;
  QString html;
  for (int i = 0; i < kErrorBitCount; ++i) {
    const bool on = (mask >> i) & 1u;
    bit_lamps_[i]->setOn(on);
    QFont font = bit_labels_[i]->font();
    font.setBold(on);
    bit_labels_[i]->setFont(font);
    bit_labels_[i]->setStyleSheet(on ? QStringLiteral("color: #b02020;") : QString());
    if (!on) continue;
    html += QStringLiteral("<p><b>%1 %2</b>: %3.<br/><i>Remedy:</i> %4.</p>")
                .arg(i)
                .arg(QLatin1String(xmate::client::errorBitName(i)),
                     QString::fromUtf8(xmate::client::errorBitMeaning(i)).toHtmlEscaped(),
                     QString::fromUtf8(xmate::client::errorBitRemedy(i)).toHtmlEscaped());
  }
  details_->setText(html.isEmpty() ? tr("No errors.") : html);
}

}  // namespace rci::ui
