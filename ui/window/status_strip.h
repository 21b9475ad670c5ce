// SPDX-License-Identifier: Apache-2.0
// StatusStrip: the status bar fields -- target, robot mode, motor power, real-time thread, loop
// rate, period jitter p99, command success rate, active error bits (in red).
#pragma once

#include <QObject>
#include <QString>

#include <xmate/rci_types.h>

class QFrame;
class QLabel;
class QStatusBar;

namespace rci::ui {

class Session;

class StatusStrip : public QObject {
  Q_OBJECT
 public:
  StatusStrip(Session& session, QStatusBar* bar);

  // Refreshes every field from session.live() (call on tick and on open/close).
  void refresh();
  // "Connecting to ..." while a session opens.
  void showConnecting();

 private:
  QLabel* field(const char* name, const QString& tooltip);
  void refreshOpen();
  void refreshClosed();
  QFrame* errorsRule() const;
  QString problemsTip() const;

  Session& session_;
  QStatusBar* bar_;
  QLabel* target_ = nullptr;
  QLabel* mode_ = nullptr;
  QLabel* motors_ = nullptr;
  QLabel* realtime_ = nullptr;
  QLabel* rate_ = nullptr;
  QLabel* jitter_ = nullptr;
  QLabel* success_ = nullptr;
  QLabel* errors_ = nullptr;
};

// "Idle", "Moving", "Hand guiding", ... for RobotState::robot_mode.
QString robotModeText(RCI::robot::RobotMode mode);

}  // namespace rci::ui
