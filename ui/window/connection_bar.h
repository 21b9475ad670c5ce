// SPDX-License-Identifier: Apache-2.0
// ConnectionBar: the toolbar that chooses the target (built-in simulator with its model, or a robot
// at HOST:PORT with a recent list) and connects / disconnects.
#pragma once

#include <QToolBar>

#include "session/session.h"

class QComboBox;
class QPushButton;
class QLabel;

namespace rci::ui {

class ConnectionBar : public QToolBar {
  Q_OBJECT
 public:
  enum class State { kDisconnected, kConnecting, kConnected };

  explicit ConnectionBar(QWidget* parent = nullptr);

  // Shows target in the chooser (kind, model, robot address).
  void setTarget(const SessionTarget& target);
  // The target the chooser shows now; false (and error set) if the robot address is invalid.
  bool currentTarget(SessionTarget& target, QString& error) const;
  void setState(State state);
  // Puts "HOST:PORT" into the robot address field (e.g. from xmate.ini).
  void setRobotAddress(const QString& host_port);
  // Reloads the robot list from recentRobots(), keeping the text.
  void refreshRecent();

 signals:
  void connectRequested(const SessionTarget& target);
  void disconnectRequested();
  void inputRefused(const QString& reason);

 private:
  void onButton();
  void updateKindWidgets();

  QComboBox* kind_ = nullptr;
  QComboBox* model_ = nullptr;
  QComboBox* robot_ = nullptr;
  QPushButton* button_ = nullptr;
  QLabel* robot_label_ = nullptr;
  QAction* robot_action_ = nullptr;
  QAction* robot_label_action_ = nullptr;
  State state_ = State::kDisconnected;
};

}  // namespace rci::ui
