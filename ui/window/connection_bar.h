// SPDX-License-Identifier: Apache-2.0
// ConnectionBar: the toolbar that chooses the target -- the built-in xMate simulator, an xMate at
// HOST:PORT (recent list), the built-in KUKA simulator, or a KUKA over RSI (its Ethernet config file,
// the address it listens on, the RSI context when several beside it name it, an optional F/T
// sensor) -- with the model, and connects / disconnects.
// GUI thread only.
#pragma once

#include <QToolBar>

#include <vector>

#include "session/session.h"

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QToolButton;

namespace rci::ui {

class ConnectionBar : public QToolBar {
  Q_OBJECT
 public:
  enum class State { kDisconnected, kConnecting, kConnected };

  explicit ConnectionBar(QWidget* parent = nullptr);

  // Shows target in the chooser (kind, the model of its family, robot address / Ethernet config
  // and sensor). Fields the target does not use keep what they showed.
  void setTarget(const SessionTarget& target);
  // The target the chooser shows now; false (and error set: what is wrong, what to enter) if the
  // robot address, the Ethernet config file or the sensor address is not usable.
  bool currentTarget(SessionTarget& target, QString& error) const;
  void setState(State state);
  // Puts "HOST:PORT" into the robot address field (e.g. from xmate.ini).
  void setRobotAddress(const QString& host_port);
  // Reloads the robot and Ethernet config lists from recentRobots() / recentRsiConfigs(), keeping
  // the texts.
  void refreshRecent();

 signals:
  void connectRequested(const SessionTarget& target);
  void disconnectRequested();
  void inputRefused(const QString& reason);

 private:
  SessionTarget::Kind currentKind() const;
  void onButton();
  void updateKindWidgets();
  void fillModels(bool kuka);
  void updateListenAddress();
  void browseRsiConfig();

  QComboBox* kind_ = nullptr;
  QComboBox* model_ = nullptr;
  QComboBox* robot_ = nullptr;
  QComboBox* rsi_config_ = nullptr;
  QToolButton* rsi_browse_ = nullptr;
  QLabel* rsi_listen_ = nullptr;
  QComboBox* rsi_context_ = nullptr;     // shown when several RSI contexts name the config
  QAction* rsi_context_action_ = nullptr;
  QString rsi_context_problem_;          // why no context can be used with the config ("" if fine)
  QString rsi_context_chosen_;           // the context last chosen there (kept while other files are tried)
  QLineEdit* ft_sensor_ = nullptr;
  QPushButton* button_ = nullptr;
  std::vector<QAction*> robot_actions_;  // shown for an xMate robot
  std::vector<QAction*> rsi_actions_;    // shown for a KUKA over RSI
  bool models_kuka_ = false;             // model_ lists the KUKA models
  QString xmate_model_ = QStringLiteral("xmate7_pro");    // the model chosen per family
  QString kuka_model_ = QStringLiteral("kr6_r900_sixx");
  State state_ = State::kDisconnected;
};

}  // namespace rci::ui
