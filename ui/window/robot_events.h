// SPDX-License-Identifier: Apache-2.0
// RobotEventWatcher: turns changes of the live state into events for the event log -- robot mode,
// motor power, hand guiding, safety stops, error bits, joints beyond their limits and the TCP
// outside the safety box -- in operator words. It compares each tick's Session::live() with the
// last one (GUI thread); polled values (motors, stops) change at ~5 Hz.
#pragma once

#include <QObject>
#include <QString>

#include <cstdint>

#include <xmate/rci_types.h>

#include "session/session.h"

namespace rci::ui {

class RobotEventWatcher : public QObject {
  Q_OBJECT
 public:
  explicit RobotEventWatcher(Session& session, QObject* parent = nullptr);

 signals:
  void event(rci::ui::Session::EventLevel level, const QString& text, const QString& detail);

 private:
  struct Seen {
    bool valid = false;
    RCI::robot::RobotMode mode = RCI::robot::RobotMode::kOther;
    int motors = 0;
    int stop = 1;
    bool guiding = false;
    uint32_t errors = 0;
    uint32_t joints_beyond = 0;  // bit j: joint j beyond its limit
    bool box_outside = false;
  };
  void onTick();
  void compare(const LiveState& live);
  void modeChanged(RCI::robot::RobotMode before, RCI::robot::RobotMode now);
  void stopChanged(int before, int now);
  void errorsChanged(uint32_t before, uint32_t now);
  void limitsChanged(uint32_t before, uint32_t now);
  void boxChanged(bool outside);
  void say(Session::EventLevel level, const QString& text, const QString& detail = QString());

  Session& session_;
  Seen seen_;
};

}  // namespace rci::ui
