// SPDX-License-Identifier: Apache-2.0
// Live-state changes as log events (robot_events.h).
#include "window/robot_events.h"

#include <QStringList>

#include "client/error_bits.h"
#include "model/robot_spec.h"
#include "text/operator_text.h"

namespace rci::ui {
namespace {

using Level = Session::EventLevel;
using RCI::robot::RobotMode;

bool guidingNow(const LiveState& live) {
  return live.state.robot_mode == RobotMode::kGuiding || (live.simulated && live.sim.dragging);
}

uint32_t beyondMask(const LiveState& live, const text::RobotView& view) {
  uint32_t mask = 0;
  if (!view.spec) return mask;
  for (const text::JointExcursion& e : text::jointsBeyondLimits(live.state.q, live.dof, view.settings, *view.spec))
    mask |= 1u << e.joint;
  return mask;
}

QStringList titlesOf(uint32_t mask) {
  QStringList titles;
  for (int bit = 0; bit < text::kErrorBitCount; ++bit)
    if ((mask >> bit) & 1u) titles << text::errorBitTitle(bit);
  return titles;
}

QStringList namesOf(uint32_t mask) {
  QStringList names;
  for (int bit = 0; bit < text::kErrorBitCount; ++bit)
    if ((mask >> bit) & 1u) names << text::errorBitName(bit);
  return names;
}

}  // namespace

RobotEventWatcher::RobotEventWatcher(Session& session, QObject* parent) : QObject(parent), session_(session) {
  connect(&session_, &Session::tick, this, &RobotEventWatcher::onTick);
  connect(&session_, &Session::closed, this, [this] { seen_ = Seen{}; });
  connect(&session_, &Session::opened, this, [this] { seen_ = Seen{}; });
}

void RobotEventWatcher::say(Level level, const QString& text, const QString& detail) { emit event(level, text, detail); }

void RobotEventWatcher::onTick() {
  if (!session_.isOpen() || session_.isReconnecting()) return;
  const LiveState& live = session_.live();
  if (!live.has_state) return;
  compare(live);
}

void RobotEventWatcher::compare(const LiveState& live) {
  const text::RobotView view = text::viewOf(session_);
  Seen now;
  now.valid = true;
  now.mode = live.state.robot_mode;
  now.motors = live.motor_state;
  now.stop = live.safety_stop;
  now.guiding = guidingNow(live);
  now.errors = xmate::client::errorMask(live.state.errors);
  now.joints_beyond = beyondMask(live, view);
  now.box_outside = text::tcpOutsideBox(live.state.toolTobase_pos_m, session_.operatorSettings().box).has_value();
  const Seen before = seen_.valid ? seen_ : Seen{true, RobotMode::kOther, 0, 1, false, 0, 0, false};
  seen_ = now;
  if (!before.valid || before.mode == RobotMode::kOther) {
    if (now.mode != RobotMode::kOther) say(Level::kInfo, tr("Robot: %1").arg(text::robotMode(now.mode)));
  } else if (now.mode != before.mode) {
    modeChanged(before.mode, now.mode);
  }
  if (now.motors != before.motors) say(Level::kInfo, now.motors == 1 ? tr("Motors on") : tr("Motors off"));
  if (now.guiding != before.guiding) say(Level::kInfo, now.guiding ? tr("Hand guiding started") : tr("Hand guiding stopped"));
  if (now.stop != before.stop) stopChanged(before.stop, now.stop);
  if (now.errors != before.errors) errorsChanged(before.errors, now.errors);
  if (now.joints_beyond != before.joints_beyond) limitsChanged(before.joints_beyond, now.joints_beyond);
  if (now.box_outside != before.box_outside) boxChanged(now.box_outside);
}

// Moving <-> Idle is the motion's own start and end (logged with the motion); hand guiding has its
// own event.
void RobotEventWatcher::modeChanged(RobotMode before, RobotMode now) {
  auto quiet = [](RobotMode m) { return m == RobotMode::kIdle || m == RobotMode::kMove || m == RobotMode::kGuiding; };
  if (quiet(before) && quiet(now)) return;
  const Level level = now == RobotMode::kReflex ? Level::kError : now == RobotMode::kUserStopped ? Level::kWarning : Level::kInfo;
  say(level, tr("Robot: %1").arg(text::robotMode(now)));
}

void RobotEventWatcher::stopChanged(int before, int now) {
  if (before == 2) say(Level::kInfo, tr("Emergency stop released"));
  if (before == 3) say(Level::kInfo, tr("Guard stop released"));
  if (now == 2) say(Level::kError, tr("Emergency stop pressed: the motors are off"));
  if (now == 3) say(Level::kWarning, tr("Guard stop active (safety door open): motion stopped"));
}

void RobotEventWatcher::errorsChanged(uint32_t before, uint32_t now) {
  const uint32_t raised = now & ~before;
  const uint32_t cleared = before & ~now;
  if (raised != 0) {
    // The new bits as the Safety panel explains them, with the joints' and box specifics.
    LiveState only_new = session_.live();
    for (int bit = 0; bit < text::kErrorBitCount; ++bit) only_new.state.errors[size_t(bit)] = (raised >> bit) & 1u;
    only_new.safety_stop = 1;
    text::RobotView view = text::viewOf(session_);
    view.live = &only_new;
    for (const text::OperatorMessage& m : text::activeProblems(view))
      if (!m.detail.isEmpty()) say(Level::kError, tr("Robot reports: %1").arg(m.line()), m.detail);
  }
  if (cleared != 0) {
    const QString titles = titlesOf(cleared).join(QStringLiteral(", "));
    say(Level::kInfo, now == 0 ? tr("Errors cleared: %1").arg(titles) : tr("Error cleared: %1").arg(titles),
        namesOf(cleared).join(QStringLiteral(", ")));
  }
}

void RobotEventWatcher::limitsChanged(uint32_t before, uint32_t now) {
  const text::RobotView view = text::viewOf(session_);
  if (!view.live || !view.spec) return;
  for (const text::JointExcursion& e : text::jointsBeyondLimits(view.live->state.q, view.live->dof, view.settings, *view.spec))
    if (((now & ~before) >> e.joint) & 1u) say(Level::kWarning, text::describe(e) + QStringLiteral(". ") + text::remedy(e) + QLatin1Char('.'));
  for (int j = 0; j < 7; ++j)
    if (((before & ~now) >> j) & 1u) say(Level::kInfo, tr("J%1 is back within its range").arg(j + 1));
}

void RobotEventWatcher::boxChanged(bool outside) {
  if (!outside) {
    say(Level::kInfo, tr("The TCP is back inside the safety box"));
    return;
  }
  const auto box = text::tcpOutsideBox(session_.live().state.toolTobase_pos_m, session_.operatorSettings().box);
  if (box) say(Level::kWarning, text::describe(*box) + QStringLiteral(". ") + text::remedy(*box) + QLatin1Char('.'));
}

}  // namespace rci::ui
