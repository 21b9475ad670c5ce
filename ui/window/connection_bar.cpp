// SPDX-License-Identifier: Apache-2.0
// The connection toolbar (connection_bar.h).
#include "window/connection_bar.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QToolButton>

#include "model/robot_spec.h"
#include "rsi/config.h"
#include "window/target_settings.h"

namespace rci::ui {
namespace {

// The xMates in the order the chooser always listed them (the default first).
constexpr xmate::XmateType kXmateOrder[] = {xmate::XMATE7_PRO, xmate::XMATE3_PRO, xmate::XMATE7, xmate::XMATE3};

QString qt(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

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
  kind_->addItem(tr("Built-in simulator"), int(SessionTarget::Kind::kSimulator));
  kind_->addItem(tr("Robot"), int(SessionTarget::Kind::kRobot));
  kind_->addItem(tr("Built-in KUKA simulator"), int(SessionTarget::Kind::kKukaSimulator));
  kind_->addItem(tr("KUKA via RSI"), int(SessionTarget::Kind::kKukaRobot));
  kind_->setItemData(0, tr("The xMate simulator built into RCI Studio"), Qt::ToolTipRole);
  kind_->setItemData(1, tr("An xMate controller on the network (RCI)"), Qt::ToolTipRole);
  kind_->setItemData(2, tr("A simulated KUKA controller running RSI, with a simulated force/torque sensor"),
                     Qt::ToolTipRole);
  kind_->setItemData(3, tr("A KUKA robot controller that sends RSI to this PC (its Ethernet config file says where)"),
                     Qt::ToolTipRole);
  kind_->setToolTip(tr("Connect to a simulator built into RCI Studio, or to a robot controller over the network"));
  addWidget(kind_);

  addWidget(caption(tr("Model"), this));
  model_ = new QComboBox(this);
  model_->setObjectName(QStringLiteral("connection.model"));
  model_->setToolTip(tr("The robot model (the simulator simulates it; a robot must be this model)"));
  addWidget(model_);
  fillModels(false);

  robot_actions_.push_back(addWidget(caption(tr("Address"), this)));
  robot_ = new QComboBox(this);
  robot_->setObjectName(QStringLiteral("connection.robot"));
  robot_->setEditable(true);
  robot_->setMinimumWidth(190);
  robot_->setInsertPolicy(QComboBox::NoInsert);
  robot_->lineEdit()->setPlaceholderText(QStringLiteral("192.168.0.160:1337"));
  robot_->setToolTip(tr("The controller's address as HOST:PORT (RCI port, default 1337); recent robots in the list"));
  robot_actions_.push_back(addWidget(robot_));

  rsi_actions_.push_back(addWidget(caption(tr("Config"), this)));
  rsi_config_ = new QComboBox(this);
  rsi_config_->setObjectName(QStringLiteral("connection.rsiConfig"));
  rsi_config_->setEditable(true);
  rsi_config_->setInsertPolicy(QComboBox::NoInsert);
  rsi_config_->setMinimumWidth(170);
  rsi_config_->setMaximumWidth(230);
  rsi_config_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  rsi_config_->setMinimumContentsLength(16);
  rsi_config_->lineEdit()->setPlaceholderText(tr("RSI_EthernetConfig.xml"));
  rsi_config_->setToolTip(tr("The RSI Ethernet config file the robot's RSI context names (copied from the "
                             "controller); this PC listens where it says. Recent files in the list."));
  rsi_actions_.push_back(addWidget(rsi_config_));
  rsi_browse_ = new QToolButton(this);
  rsi_browse_->setObjectName(QStringLiteral("connection.rsiBrowse"));
  rsi_browse_->setText(QStringLiteral("…"));
  rsi_browse_->setToolTip(tr("Choose the RSI Ethernet config file"));
  rsi_actions_.push_back(addWidget(rsi_browse_));
  rsi_listen_ = new QLabel(this);
  rsi_listen_->setObjectName(QStringLiteral("connection.rsiListen"));
  rsi_listen_->setContentsMargins(6, 0, 4, 0);
  rsi_actions_.push_back(addWidget(rsi_listen_));
  rsi_context_ = new QComboBox(this);
  rsi_context_->setObjectName(QStringLiteral("connection.rsiContext"));
  rsi_context_->setToolTip(tr("Several RSI contexts beside the Ethernet config use it: choose the one the robot runs"));
  rsi_context_action_ = addWidget(rsi_context_);
  rsi_actions_.push_back(addWidget(caption(tr("F/T sensor"), this)));
  ft_sensor_ = new QLineEdit(this);
  ft_sensor_->setObjectName(QStringLiteral("connection.ftSensor"));
  ft_sensor_->setPlaceholderText(tr("none"));
  ft_sensor_->setFixedWidth(130);
  ft_sensor_->setToolTip(tr("The force/torque sensor's address as HOST or HOST:PORT (RDT port 49152 by default); "
                            "empty: no sensor, so no hand guiding"));
  rsi_actions_.push_back(addWidget(ft_sensor_));

  auto* spacer = new QWidget(this);
  spacer->setFixedWidth(8);
  addWidget(spacer);
  button_ = new QPushButton(tr("Connect"), this);
  button_->setObjectName(QStringLiteral("connection.connect"));
  button_->setMinimumWidth(110);
  addWidget(button_);

  refreshRecent();
  connect(kind_, &QComboBox::currentIndexChanged, this, [this] { updateKindWidgets(); });
  connect(model_, &QComboBox::currentIndexChanged, this, [this] {
    if (model_->currentIndex() < 0) return;
    (models_kuka_ ? kuka_model_ : xmate_model_) = model_->currentData().toString();
  });
  connect(button_, &QPushButton::clicked, this, [this] { onButton(); });
  connect(robot_->lineEdit(), &QLineEdit::returnPressed, this, [this] {
    if (state_ == State::kDisconnected) onButton();
  });
  connect(rsi_config_, &QComboBox::currentTextChanged, this, [this] { updateListenAddress(); });
  connect(rsi_config_->lineEdit(), &QLineEdit::returnPressed, this, [this] {
    if (state_ == State::kDisconnected) onButton();
  });
  connect(ft_sensor_, &QLineEdit::returnPressed, this, [this] {
    if (state_ == State::kDisconnected) onButton();
  });
  connect(rsi_context_, &QComboBox::currentIndexChanged, this,
          [this] { rsi_context_chosen_ = rsi_context_->currentData().toString(); });
  connect(rsi_browse_, &QToolButton::clicked, this, [this] { browseRsiConfig(); });
  updateKindWidgets();
  updateListenAddress();
  setState(State::kDisconnected);
}

SessionTarget::Kind ConnectionBar::currentKind() const { return SessionTarget::Kind(kind_->currentData().toInt()); }

void ConnectionBar::setTarget(const SessionTarget& target) {
  if (target.isKuka()) {
    QString name;
    if (parseKukaModel(target.kuka_model, name)) kuka_model_ = name;
  } else {
    xmate_model_ = qt(xmate::model::robotSpec(target.type).name);
  }
  kind_->setCurrentIndex(kind_->findData(int(target.kind)));
  if (target.kind == SessionTarget::Kind::kRobot || robot_->currentText().isEmpty())
    robot_->setEditText(QStringLiteral("%1:%2").arg(target.host).arg(target.port));
  if (!target.rsi_config.isEmpty() &&
      (target.kind == SessionTarget::Kind::kKukaRobot || rsi_config_->currentText().isEmpty())) {
    if (rsi_config_->findText(target.rsi_config) < 0) rsi_config_->insertItem(0, target.rsi_config);
    rsi_config_->setEditText(target.rsi_config);
  }
  if (target.kind == SessionTarget::Kind::kKukaRobot) {
    ft_sensor_->setText(target.ft_sensor);
    const int context = rsi_context_->findData(QFileInfo(target.rsi_context).absoluteFilePath());
    if (!target.rsi_context.isEmpty() && context >= 0) rsi_context_->setCurrentIndex(context);  // remembers it
  }
  updateKindWidgets();
  // The kind may not have changed: show the target's model in any case.
  model_->setCurrentIndex(model_->findData(models_kuka_ ? kuka_model_ : xmate_model_));
}

bool ConnectionBar::currentTarget(SessionTarget& target, QString& error) const {
  target = SessionTarget{};
  target.kind = currentKind();
  const QString model = model_->currentData().toString();
  if (!target.isKuka()) {
    if (const xmate::model::RobotSpec* spec = xmate::model::findXmateSpec(model.toStdString())) target.type = spec->type;
  } else {
    target.kuka_model = model;
  }
  switch (target.kind) {
    case SessionTarget::Kind::kSimulator:
      target.loopback = true;  // the IO panel's DO switches then light the DI lamps
      return true;
    case SessionTarget::Kind::kRobot:
      return parseHostPort(robot_->currentText(), target.host, target.port, error);
    case SessionTarget::Kind::kKukaSimulator:
      return true;
    case SessionTarget::Kind::kKukaRobot: {
      QString listen;
      if (!rsiListenAddress(rsi_config_->currentText(), listen, error)) return false;
      if (!rsi_context_problem_.isEmpty()) {
        error = rsi_context_problem_;
        return false;
      }
      target.rsi_config = QFileInfo(rsi_config_->currentText().trimmed()).absoluteFilePath();
      if (rsi_context_->count() > 1) target.rsi_context = rsi_context_->currentData().toString();
      return parseSensorAddress(ft_sensor_->text(), target.ft_sensor, error);
    }
  }
  return false;
}

void ConnectionBar::setState(State state) {
  state_ = state;
  const bool idle = state == State::kDisconnected;
  for (QWidget* widget : std::initializer_list<QWidget*>{kind_, model_, robot_, rsi_config_, rsi_browse_, rsi_context_,
                                                                  ft_sensor_})
    widget->setEnabled(idle);
  button_->setText(idle ? tr("Connect") : (state == State::kConnecting ? tr("Cancel") : tr("Disconnect")));
  button_->setToolTip(idle ? tr("Connect to the chosen target") : tr("Stop any motion and disconnect"));
}

void ConnectionBar::setRobotAddress(const QString& host_port) { robot_->setEditText(host_port); }

void ConnectionBar::refreshRecent() {
  const QString text = robot_->currentText();
  robot_->clear();
  robot_->addItems(recentRobots());
  robot_->setEditText(text);
  const QString config = rsi_config_->currentText();
  rsi_config_->blockSignals(true);
  rsi_config_->clear();
  rsi_config_->addItems(recentRsiConfigs());
  rsi_config_->setEditText(config);
  rsi_config_->blockSignals(false);
  updateListenAddress();
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

// Only the fields of the chosen kind are shown (the bar must fit a 1366 px screen).
void ConnectionBar::updateKindWidgets() {
  const SessionTarget::Kind kind = currentKind();
  for (QAction* action : robot_actions_) action->setVisible(kind == SessionTarget::Kind::kRobot);
  for (QAction* action : rsi_actions_) action->setVisible(kind == SessionTarget::Kind::kKukaRobot);
  rsi_context_action_->setVisible(kind == SessionTarget::Kind::kKukaRobot && rsi_context_->count() > 1);
  const bool kuka = kind == SessionTarget::Kind::kKukaSimulator || kind == SessionTarget::Kind::kKukaRobot;
  if (kuka != models_kuka_ || model_->count() == 0) fillModels(kuka);
}

// The models of one family: the xMates, or the KUKA arms; the one last chosen of it selected.
void ConnectionBar::fillModels(bool kuka) {
  models_kuka_ = kuka;
  const QString wanted = kuka ? kuka_model_ : xmate_model_;
  model_->blockSignals(true);
  model_->clear();
  if (kuka) {
    for (const xmate::model::RobotSpec& spec : xmate::model::allRobotSpecs())
      if (spec.family == xmate::model::RobotFamily::kKuka) model_->addItem(qt(spec.display_name), qt(spec.name));
  } else {
    // The xMates by the names the window uses everywhere else ("xMate7 Pro").
    for (xmate::XmateType type : kXmateOrder) model_->addItem(modelName(type), qt(xmate::model::robotSpec(type).name));
  }
  model_->setCurrentIndex(std::max(0, model_->findData(wanted)));
  model_->blockSignals(false);
}

// "listens on 192.168.1.20:49152" beside the Ethernet config, or what is wrong with the file; the
// RSI contexts beside it that name it (a chooser when there are several).
void ConnectionBar::updateListenAddress() {
  const QString path = rsi_config_->currentText().trimmed();
  rsi_context_->blockSignals(true);
  rsi_context_->clear();
  rsi_context_problem_.clear();
  QString listen, error;
  if (path.isEmpty()) {
    rsi_listen_->setText(tr("choose the file"));
    rsi_listen_->setToolTip(tr("Choose the robot's RSI Ethernet config file with the … button"));
    rsi_listen_->setStyleSheet(QString());
  } else if (!rsiListenAddress(path, listen, error)) {
    rsi_listen_->setText(tr("file not usable"));
    rsi_listen_->setToolTip(error);
    rsi_listen_->setStyleSheet(QStringLiteral("color: #c62828;"));
  } else {
    for (const std::string& context : xmate::rsi::contextsNaming(path.toStdString())) {
      const QFileInfo info(QString::fromStdString(context));
      rsi_context_->addItem(info.fileName().section(QLatin1Char('.'), 0, 0), info.absoluteFilePath());
    }
    rsi_context_->setCurrentIndex(std::max(0, rsi_context_->findData(rsi_context_chosen_)));
    rsi_listen_->setText(tr("listens on %1").arg(listen));
    rsi_listen_->setStyleSheet(QString());
    if (rsi_context_->count() == 0) {
      rsi_context_problem_ =
          tr("No RSI context (NAME.rsi.xml) beside %1 uses it. Copy the context the robot runs (from the "
             "controller's C:\\KRC\\ROBOTER\\Config\\User\\Common\\SensorInterface) into the same folder.")
              .arg(QFileInfo(path).fileName());
      rsi_listen_->setToolTip(rsi_context_problem_);
      rsi_listen_->setStyleSheet(QStringLiteral("color: #b26a00;"));
    } else {
      rsi_listen_->setToolTip(tr("This PC waits for the robot's RSI datagrams at %1 (from %2); the robot runs %3")
                                  .arg(listen, QFileInfo(path).fileName(),
                                       rsi_context_->count() == 1 ? rsi_context_->itemText(0)
                                                                  : tr("the RSI context chosen beside it")));
    }
  }
  rsi_context_->blockSignals(false);
  rsi_context_action_->setVisible(currentKind() == SessionTarget::Kind::kKukaRobot && rsi_context_->count() > 1);
}

void ConnectionBar::browseRsiConfig() {
  const QString current = rsi_config_->currentText().trimmed();
  const QString start = current.isEmpty() ? QDir::homePath() : QFileInfo(current).absolutePath();
  const QString path = QFileDialog::getOpenFileName(this, tr("The robot's RSI Ethernet config"), start,
                                                    tr("RSI Ethernet config (*.xml);;All files (*)"));
  if (path.isEmpty()) return;
  rsi_config_->setEditText(QDir::toNativeSeparators(path));
}

}  // namespace rci::ui
