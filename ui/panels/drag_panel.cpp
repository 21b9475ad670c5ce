// SPDX-License-Identifier: Apache-2.0
// Drag panel: validated startDrag (parameter_checks), stopDrag, guiding state from the live state.
#include "panels/drag_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

DragPanel::DragPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("drag"), tr("Drag"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kBuiltInGuiding));
  auto* group = new QGroupBox(tr("Hand guiding"), this);
  auto* form = new QFormLayout(group);
  space_ = new QComboBox(group);
  space_->setObjectName(QStringLiteral("drag.space"));
  space_->addItem(tr("Joint space"), 1);
  space_->addItem(tr("Cartesian space"), 2);
  space_->setToolTip(tr("Joint space: every joint yields freely. Cartesian space: the TCP yields in the chosen "
                        "directions and holds the others"));
  type_ = new QComboBox(group);
  type_->setObjectName(QStringLiteral("drag.type"));
  type_->addItem(tr("Translation only"), 1);
  type_->addItem(tr("Rotation only"), 2);
  type_->addItem(tr("Free"), 3);
  type_->setToolTip(tr("Which motions the hand may guide (Cartesian space); joint space is always free"));
  form->addRow(tr("Space"), space_);
  form->addRow(tr("Type"), type_);

  auto* state_row = new QHBoxLayout;
  lamp_ = new Lamp(lampAmber(), group);
  lamp_->setObjectName(QStringLiteral("drag.lamp"));
  lamp_->setToolTip(tr("On while the robot is in hand-guiding mode"));
  state_ = new QLabel(tr("Not guiding"), group);
  state_->setObjectName(QStringLiteral("drag.state"));
  state_row->addWidget(lamp_);
  state_row->addWidget(state_, 1);
  form->addRow(tr("State"), state_row);
  message_ = new MessageLine(QStringLiteral("drag.message"), group);
  form->addRow(message_);

  auto* buttons = new QHBoxLayout;
  auto* start = new QPushButton(tr("Start guiding"), group);
  start->setObjectName(QStringLiteral("drag.start"));
  start->setToolTip(tr("Start hand guiding: the arm yields to your hand; needs the motors on and no motion running"));
  auto* stop = new QPushButton(tr("Stop guiding"), group);
  stop->setObjectName(QStringLiteral("drag.stop"));
  stop->setToolTip(tr("Stop hand guiding: the arm stops and holds its position"));
  addMotionWidget(start);
  addSendWidget(stop);
  buttons->addStretch(1);
  buttons->addWidget(start);
  buttons->addWidget(stop);
  form->addRow(buttons);
  body()->addWidget(group);

  space_->setCurrentIndex(space_->findData(loadValue(QStringLiteral("space"), 2).toInt()));
  type_->setCurrentIndex(type_->findData(loadValue(QStringLiteral("type"), 3).toInt()));
  spaceChanged();
  connect(space_, &QComboBox::currentIndexChanged, this, &DragPanel::spaceChanged);
  connect(start, &QPushButton::clicked, this, &DragPanel::start);
  connect(stop, &QPushButton::clicked, this, [this] {
    send(tr("stop guiding"), [](xmate::Robot& r) { r.stopDrag(); });
  });
}

void DragPanel::spaceChanged() {
  // Joint-space guiding is always free (docs/api.md, "Settings and their ranges", startDrag): offer only that.
  const bool joint = space_->currentData().toInt() == 1;
  if (joint) type_->setCurrentIndex(type_->findData(3));
  type_->setEnabled(!joint);
}

void DragPanel::start() {
  const int space = space_->currentData().toInt();
  const int type = type_->currentData().toInt();
  const xmate::model::ParameterProblem error = xmate::model::checkDrag(space, type);
  if (!error.empty()) {
    message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  message_->clearMessage();
  saveValue(QStringLiteral("space"), space);
  saveValue(QStringLiteral("type"), type);
  send(tr("start guiding"), [space, type](xmate::Robot& r) { r.startDrag(space, type); });
}

void DragPanel::refresh(const LiveState& live) {
  const bool guiding = (live.has_state && live.state.robot_mode == RCI::robot::RobotMode::kGuiding) ||
                       (live.simulated && live.sim.dragging);
  lamp_->setOn(guiding);
  state_->setText(guiding ? tr("Guiding: move the arm by hand") : tr("Not guiding"));
}

void DragPanel::sessionClosed() {
  lamp_->setOn(false);
  state_->setText(tr("Not connected"));
}

}  // namespace rci::ui
