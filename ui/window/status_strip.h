// SPDX-License-Identifier: Apache-2.0
// StatusStrip: the status bar fields -- target, robot mode, motor power, real-time thread, loop
// rate, period jitter p99, command success rate, active error bits (in red); on a KUKA over RSI
// instead: the RSI phase, cycle, late answers, answer time p99, real-time thread and F/T sensor.
// GUI thread only.
#pragma once

#include <QObject>
#include <QString>

#include <vector>

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
  void refreshRsi();
  void refreshClosed();
  // Shows the fields of one family (the RSI ones or the xMate's) with their rules.
  void showFamily(bool rsi);
  void showField(QLabel* label, bool shown);
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
  QLabel* rsi_ = nullptr;      // RSI phase
  QLabel* cycle_ = nullptr;    // RSI cycle
  QLabel* late_ = nullptr;     // late answers: the robot's count and the PC's
  QLabel* answer_ = nullptr;   // the PC's answer time p99
  QLabel* sensor_ = nullptr;   // the F/T sensor
  std::vector<QLabel*> xmate_fields_, rsi_fields_;
  int family_shown_ = -1;      // 0 xMate, 1 RSI, -1 not yet
};

// "Idle", "Moving", "Hand guiding", ... for RobotState::robot_mode.
QString robotModeText(RCI::robot::RobotMode mode);

}  // namespace rci::ui
