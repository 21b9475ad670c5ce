// SPDX-License-Identifier: Apache-2.0
// The connection toolbar (connection_bar.h).
#include "window/connection_bar.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include "window/target_settings.h"

namespace rci::ui {
namespace {

constexpr xmate::XmateType kModels[] = {xmate::XMATE7_PRO, xmate::XMATE3_PRO, xmate::XMATE7, xmate::XMATE3};

QLabel* caption(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setContentsMargins(8, 0, 4, 0);
  return label;
}

}  // namespace

ConnectionBar::ConnectionBar(QWidget* parent) : QToolBar(tr("Connection"), parent) {
  setObjectName(QStringLiteral("toolbar.connection"));
  setMovable(false);

  addWidget(caption(tr("Target"), this));
  kind_ = new QComboBox(this);
  kind_->setObjectName(QStringLiteral("connection.kind"));
  kind_->addItem(tr("Built-in simulator"));
  kind_->addItem(tr("Robot"));
  kind_->setToolTip(tr("Connect to the simulator built into RCI Studio, or to a robot controller over the network"));
  addWidget(kind_);

  addWidget(caption(tr("Model"), this));
  model_ = new QComboBox(this);
  model_->setObjectName(QStringLiteral("connection.model"));
  for (xmate::XmateType type : kModels) model_->addItem(modelName(type), int(type));
  model_->setToolTip(tr("The robot model (the simulator simulates it; a robot must be this model)"));
  addWidget(model_);

  robot_label_action_ = addWidget(caption(tr("Address"), this));
  robot_ = new QComboBox(this);
  robot_->setObjectName(QStringLiteral("connection.robot"));
  robot_->setEditable(true);
  robot_->setMinimumWidth(190);
  robot_->setInsertPolicy(QComboBox::NoInsert);
  robot_->lineEdit()->setPlaceholderText(QStringLiteral("192.168.0.160:1337"));
  robot_->setToolTip(tr("The controller's address as HOST:PORT (RCI port, default 1337); recent robots in the list"));
  robot_action_ = addWidget(robot_);

  auto* spacer = new QWidget(this);
  spacer->setFixedWidth(8);
  addWidget(spacer);
  button_ = new QPushButton(tr("Connect"), this);
  button_->setObjectName(QStringLiteral("connection.connect"));
  button_->setMinimumWidth(110);
  addWidget(button_);

  refreshRecent();
  connect(kind_, &QComboBox::currentIndexChanged, this, [this] { updateKindWidgets(); });
  connect(button_, &QPushButton::clicked, this, [this] { onButton(); });
  connect(robot_->lineEdit(), &QLineEdit::returnPressed, this, [this] {
    if (state_ == State::kDisconnected) onButton();
  });
  updateKindWidgets();
  setState(State::kDisconnected);
}

void ConnectionBar::setTarget(const SessionTarget& target) {
  kind_->setCurrentIndex(target.kind == SessionTarget::Kind::kRobot ? 1 : 0);
  model_->setCurrentIndex(model_->findData(int(target.type)));
  if (target.kind == SessionTarget::Kind::kRobot || robot_->currentText().isEmpty())
    robot_->setEditText(QStringLiteral("%1:%2").arg(target.host).arg(target.port));
  updateKindWidgets();
}

bool ConnectionBar::currentTarget(SessionTarget& target, QString& error) const {
  target = SessionTarget{};
  target.type = xmate::XmateType(model_->currentData().toInt());
  if (kind_->currentIndex() == 0) {
    target.kind = SessionTarget::Kind::kSimulator;
    target.loopback = true;  // the IO panel's DO switches then light the DI lamps
    return true;
  }
  target.kind = SessionTarget::Kind::kRobot;
  return parseHostPort(robot_->currentText(), target.host, target.port, error);
}

void ConnectionBar::setState(State state) {
  state_ = state;
  const bool idle = state == State::kDisconnected;
  kind_->setEnabled(idle);
  model_->setEnabled(idle);
  robot_->setEnabled(idle);
  button_->setText(idle ? tr("Connect") : (state == State::kConnecting ? tr("Cancel") : tr("Disconnect")));
  button_->setToolTip(idle ? tr("Connect to the chosen target") : tr("Stop any motion and disconnect"));
}

void ConnectionBar::setRobotAddress(const QString& host_port) { robot_->setEditText(host_port); }

void ConnectionBar::refreshRecent() {
  const QString text = robot_->currentText();
  robot_->clear();
  robot_->addItems(recentRobots());
  robot_->setEditText(text);
}

void ConnectionBar::onButton() {
  if (state_ != State::kDisconnected) {
    emit disconnectRequested();
    return;
  }
  SessionTarget target;
  QString error;
  if (!currentTarget(target, error)) {
    emit inputRefused(error);
    return;
  }
  emit connectRequested(target);
}

void ConnectionBar::updateKindWidgets() {
  const bool robot = kind_->currentIndex() == 1;
  robot_action_->setVisible(robot);
  robot_label_action_->setVisible(robot);
}

}  // namespace rci::ui
