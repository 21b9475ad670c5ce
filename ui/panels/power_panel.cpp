// SPDX-License-Identifier: Apache-2.0
// Power panel: buttons for setMotorPower(1/0), the motor lamp (polled motor state), reboot.
#include "panels/power_panel.h"

#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {

PowerPanel::PowerPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("power"), tr("Power"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kPowerControl));
  auto* motors = new QGroupBox(tr("Motor power"), this);
  auto* grid = new QGridLayout(motors);
  motor_lamp_ = new Lamp(lampGreen(), motors);
  motor_lamp_->setObjectName(QStringLiteral("power.lamp"));
  motor_lamp_->setToolTip(tr("Motor power as the controller reports it"));
  motor_text_ = new QLabel(tr("Motors off"), motors);
  motor_text_->setObjectName(QStringLiteral("power.state"));
  auto* on = new QPushButton(tr("Power on"), motors);
  on->setObjectName(QStringLiteral("power.on"));
  on->setToolTip(tr("Switch the motors on; not possible while the emergency stop is pressed"));
  auto* off = new QPushButton(tr("Power off"), motors);
  off->setObjectName(QStringLiteral("power.off"));
  off->setToolTip(tr("Switch the motors off; a running motion ends and the brakes hold"));
  auto* state_row = new QHBoxLayout;
  state_row->addWidget(motor_lamp_);
  state_row->addWidget(motor_text_, 1);
  grid->addLayout(state_row, 0, 0, 1, 2);
  grid->addWidget(on, 1, 0);
  grid->addWidget(off, 1, 1);
  body()->addWidget(motors);

  auto* controller = new QGroupBox(tr("Controller"), this);
  auto* row = new QHBoxLayout(controller);
  auto* reboot = new QPushButton(tr("Reboot controller…"), controller);
  reboot->setObjectName(QStringLiteral("power.reboot"));
  reboot->setToolTip(tr("Restart the robot controller: the session drops, tool, load and limits return to "
                        "their defaults"));
  row->addWidget(reboot);
  row->addStretch(1);
  body()->addWidget(controller);

  addSendWidget(on);
  addSendWidget(off);
  addSendWidget(reboot);
  connect(on, &QPushButton::clicked, this, [this] {
    send(tr("power on"), [](xmate::Robot& r) { r.setMotorPower(1); });
  });
  connect(off, &QPushButton::clicked, this, [this] {
    send(tr("power off"), [](xmate::Robot& r) { r.setMotorPower(0); });
  });
  connect(reboot, &QPushButton::clicked, this, &PowerPanel::rebootWithConfirmation);
}

void PowerPanel::rebootWithConfirmation() {
  const auto answer = QMessageBox::question(
      this, tr("Reboot controller"),
      tr("Reboot the robot controller?\n\nThe motors switch off, the connection drops and tool, payload, "
         "limits and filters return to their defaults. The window reconnects when the controller is back."),
      QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
  if (answer != QMessageBox::Yes) return;
  send(tr("reboot"), [](xmate::Robot& r) { r.rebootRobot(); });
}

void PowerPanel::refresh(const LiveState& live) {
  const bool on = live.motor_state == 1;
  motor_lamp_->setOn(on);
  motor_text_->setText(on ? tr("Motors on") : tr("Motors off"));
}

void PowerPanel::sessionClosed() {
  motor_lamp_->setOn(false);
  motor_text_->setText(tr("Not connected"));
}

}  // namespace rci::ui
