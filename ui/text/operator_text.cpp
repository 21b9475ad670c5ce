// SPDX-License-Identifier: Apache-2.0
// Operator text for the 20 error bits, robot modes and safety stops, and the list of everything
// wrong right now (operator_text.h). Limits and the box: limit_text.cpp; failures: failure_text.cpp.
#include "text/operator_text.h"

#include <QCoreApplication>

#include "client/error_bits.h"
#include "model/robot_spec.h"
#include "session/session.h"

namespace rci::ui::text {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("OperatorText", text); }

// Bits whose cure is the same: recover, then move more gently.
enum class Family { kJointLimit, kBox, kElbow, kGentler, kCommandJoint, kCommandBox, kCommandElbow, kCollision, kSingular, kLost };

struct BitText {
  const char* title;
  const char* what;
  Family family;
};

constexpr BitText kBits[kErrorBitCount] = {
    {QT_TRANSLATE_NOOP("OperatorText", "Joint position limit reached"),
     QT_TRANSLATE_NOOP("OperatorText", "A joint was measured beyond its position limit and the robot stopped."), Family::kJointLimit},
    {QT_TRANSLATE_NOOP("OperatorText", "Outside the safety box"),
     QT_TRANSLATE_NOOP("OperatorText", "The tool (TCP) left the safety box, so the motors were switched off."), Family::kBox},
    {QT_TRANSLATE_NOOP("OperatorText", "Elbow angle limit reached"),
     QT_TRANSLATE_NOOP("OperatorText", "The arm's elbow angle was measured beyond its limit and the robot stopped."), Family::kElbow},
    {QT_TRANSLATE_NOOP("OperatorText", "Joint moved too fast"),
     QT_TRANSLATE_NOOP("OperatorText", "A joint was measured moving faster than allowed and the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Tool moved too fast"),
     QT_TRANSLATE_NOOP("OperatorText", "The tool (TCP) was measured moving faster than allowed and the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Joint accelerated too hard"),
     QT_TRANSLATE_NOOP("OperatorText", "A joint was measured speeding up or braking harder than allowed and the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Tool accelerated too hard"),
     QT_TRANSLATE_NOOP("OperatorText", "The tool (TCP) was measured speeding up or braking harder than allowed and the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion aimed beyond a joint limit"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion asked a joint to go beyond its limit (a soft limit or the robot's own range), so the robot stopped."), Family::kCommandJoint},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion aimed outside the workspace"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion asked the tool to go outside the allowed workspace or the safety box, so the robot stopped."), Family::kCommandBox},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion aimed beyond the elbow limit"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion asked for an elbow angle beyond its range, so the robot stopped."), Family::kCommandElbow},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion too fast for a joint"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion was too fast for one of the joints, so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion too fast for the tool"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion was too fast for the tool (TCP), so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Joint acceleration too high"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion sped up or braked too sharply for a joint, so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Tool acceleration too high"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion sped up or braked too sharply for the tool (TCP), so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Motion too jerky"),
     QT_TRANSLATE_NOOP("OperatorText", "The motion changed its acceleration too abruptly, so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Collision detected"),
     QT_TRANSLATE_NOOP("OperatorText", "The robot felt an unexpected force on the arm and switched its motors off."), Family::kCollision},
    {QT_TRANSLATE_NOOP("OperatorText", "Awkward pose on a straight path"),
     QT_TRANSLATE_NOOP("OperatorText", "During a straight-line or arc motion the arm reached a pose it cannot steer through "
                                       "(arm fully stretched or two wrist axes in line), so the robot stopped."), Family::kSingular},
    {QT_TRANSLATE_NOOP("OperatorText", "Torque changed too abruptly"),
     QT_TRANSLATE_NOOP("OperatorText", "The motors were asked to change their torque too abruptly, so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Torque too high"),
     QT_TRANSLATE_NOOP("OperatorText", "The motors were asked for more torque than allowed, so the robot stopped."), Family::kGentler},
    {QT_TRANSLATE_NOOP("OperatorText", "Commands lost (connection or computer too slow)"),
     QT_TRANSLATE_NOOP("OperatorText", "Too many motion commands in a row did not reach the robot in time (the network or this "
                                       "computer was too slow), or a drive reported a fault. The robot stopped."), Family::kLost},
};

QString familyTodo(Family family) {
  switch (family) {
    case Family::kJointLimit:
      return tr("Press Recover in the Safety panel, then jog that joint back (Jog panel) or guide it back towards its "
                "range (Drag panel).");
    case Family::kBox:
      return tr("Press Recover in the Safety panel, then Power on in the Power panel, then guide or jog the TCP back "
                "into the box (the Safety box panel shows it).");
    case Family::kElbow:
      return tr("Press Recover in the Safety panel, then jog or guide the arm back until the elbow is within its range.");
    case Family::kGentler:
      return tr("Press Recover in the Safety panel. Then move more gently: lower the speed on the Jog panel's slider, "
                "the Program panel's speed override or the instruction's speed; when guiding by hand, move the arm "
                "more slowly.");
    case Family::kCommandJoint:
      return tr("Press Recover in the Safety panel. Then re-teach the target inside the joint range, or widen the "
                "limits in the Soft limits panel.");
    case Family::kCommandBox:
      return tr("Press Recover in the Safety panel. Then re-teach the target inside the safety box (the Safety box "
                "panel shows it) or enlarge the box.");
    case Family::kCommandElbow:
      return tr("Press Recover in the Safety panel, then re-teach the target with the elbow in a more natural position.");
    case Family::kCollision:
      return tr("Check that nothing is in the way, press Recover in the Safety panel, then Power on in the Power panel. "
                "If the robot touched nothing, raise the thresholds in the Collision panel or correct the payload in "
                "the Tool & payload panel.");
    case Family::kSingular:
      return tr("Press Recover in the Safety panel. Then reach that point with a joint move (type J in the Program "
                "panel) or re-teach the waypoints away from that pose.");
    case Family::kLost:
      return tr("Press Recover in the Safety panel (and Power on in the Power panel if the motors are off), then try "
                "again. If it repeats, close other programs, check the network cable, and run rci-cli doctor to check "
                "this computer's real-time setup.");
  }
  return {};
}

bool validBit(int bit) { return bit >= 0 && bit < kErrorBitCount; }

// Appends a sentence end if text has none.
QString sentence(const QString& text) {
  const QString t = text.trimmed();
  if (t.isEmpty()) return t;
  const QChar last = t.back();
  if (last == QLatin1Char('.') || last == QLatin1Char('!') || last == QLatin1Char('?')) return t;
  return t + QLatin1Char('.');
}

OperatorMessage stopMessage(int safety_stop) {
  if (safety_stop == 2)
    return {tr("Emergency stop pressed"), tr("The motors are off and the robot cannot move."),
            tr("Release the emergency stop, press Recover in the Safety panel, then Power on in the Power panel."),
            QStringLiteral("safety stop state 2"), false};
  return {tr("Guard stop active"), tr("The guard (safety door) is open: the robot stopped and cannot start a motion."),
          tr("Close the guard, then start the motion again."), QStringLiteral("safety stop state 3"), false};
}

// One message for all active bits that share the "move more gently" cure.
OperatorMessage gentlerMessage(const std::vector<int>& bits) {
  OperatorMessage m;
  QStringList titles, names;
  for (int bit : bits) {
    titles << errorBitTitle(bit);
    names << errorBitName(bit);
  }
  m.title = titles.join(QStringLiteral(", "));
  m.what = bits.size() == 1 ? tr(kBits[bits.front()].what)
                            : tr("The motion was too fast or too jerky for the robot, so it stopped.");
  m.todo = familyTodo(Family::kGentler);
  m.detail = names.join(QStringLiteral(", "));
  return m;
}

}  // namespace

QString OperatorMessage::line() const {
  QStringList parts;
  for (const QString& part : {title, what, todo})
    if (!part.trimmed().isEmpty()) parts << sentence(part);
  QString text = parts.join(QLatin1Char(' '));
  if (detail_inline && !detail.isEmpty()) text += QStringLiteral(" (%1)").arg(detail);
  return text;
}

QString OperatorMessage::html() const {
  QString text = QStringLiteral("<b>%1</b>").arg(title.toHtmlEscaped());
  if (!what.isEmpty()) text += QStringLiteral("<br/>") + sentence(what).toHtmlEscaped();
  if (!todo.isEmpty()) text += QStringLiteral("<br/><i>%1</i> %2").arg(tr("What to do:"), sentence(todo).toHtmlEscaped());
  if (detail_inline && !detail.isEmpty()) text += QStringLiteral("<br/><small>(%1)</small>").arg(detail.toHtmlEscaped());
  return text;
}

QString errorBitTitle(int bit) { return validBit(bit) ? tr(kBits[bit].title) : tr("Unknown error"); }

QString errorBitName(int bit) { return QString::fromLatin1(xmate::client::errorBitName(bit)); }

OperatorMessage errorBit(int bit) {
  if (!validBit(bit)) return {tr("Unknown error"), {}, tr("Press Recover in the Safety panel."), errorBitName(bit), false};
  return {tr(kBits[bit].title), tr(kBits[bit].what), familyTodo(kBits[bit].family), errorBitName(bit), false};
}

QString robotMode(RCI::robot::RobotMode mode) {
  using RCI::robot::RobotMode;
  switch (mode) {
    case RobotMode::kIdle: return tr("Idle");
    case RobotMode::kMove: return tr("Moving");
    case RobotMode::kGuiding: return tr("Hand guiding");
    case RobotMode::kReflex: return tr("Stopped by an error");
    case RobotMode::kUserStopped: return tr("Stopped by e-stop/guard stop");
    case RobotMode::kAutomaticErrorRecovery: return tr("Recovering");
    case RobotMode::kOther: break;
  }
  return tr("Other");
}

QString safetyStop(int safety_stop) {
  switch (safety_stop) {
    case 2: return tr("Emergency stop pressed");
    case 3: return tr("Guard stop active");
    default: return tr("No stop");
  }
}

RobotView viewOf(Session& session) {
  RobotView view;
  if (session.isOpen() && session.live().has_state) view.live = &session.live();
  view.settings = &session.operatorSettings();
  xmate::Robot* robot = session.robot();
  view.spec = &xmate::model::robotSpec(robot ? robot->type() : session.target().type);
  return view;
}

OperatorMessage errorBit(int bit, const RobotView& view) {
  OperatorMessage m = errorBit(bit);
  if (!validBit(bit) || !view.live) return m;
  const RCI::robot::RobotState& state = view.live->state;
  const Family family = kBits[bit].family;
  if ((family == Family::kJointLimit || family == Family::kCommandJoint) && view.spec) {
    const auto beyond = jointsBeyondLimits(state.q, view.live->dof, view.settings, *view.spec);
    if (beyond.empty()) return m;
    QStringList what, todo;
    for (const JointExcursion& e : beyond) {
      what << describe(e);
      todo << remedy(e);
    }
    m.what = what.join(QStringLiteral("; ")) + tr(". The robot stopped.");
    // Recover first (the robot moves only without errors), then every joint's way back.
    m.todo = tr("Press Recover in the Safety panel, then bring it back. %1.").arg(todo.join(QStringLiteral(". ")));
  }
  if ((family == Family::kBox || family == Family::kCommandBox) && view.settings) {
    if (const auto box = tcpOutsideBox(state.toolTobase_pos_m, view.settings->box)) {
      m.what = describe(*box) + tr(". The motors were switched off.");
      m.todo = tr("Press Recover in the Safety panel, then Power on in the Power panel, then %1 (the Safety box panel "
                  "shows the box).")
                   .arg(remedy(*box).left(1).toLower() + remedy(*box).mid(1));
    }
  }
  return m;
}

std::vector<OperatorMessage> activeProblems(const RobotView& view) {
  std::vector<OperatorMessage> out;
  if (!view.live) return out;
  const LiveState& live = *view.live;
  if (live.safety_stop == 2 || live.safety_stop == 3) out.push_back(stopMessage(live.safety_stop));
  const auto& errors = live.state.errors;
  if (errors[15]) out.push_back(errorBit(15, view));  // the collision first: people may be involved
  std::vector<int> gentler;
  for (int bit = 0; bit < kErrorBitCount; ++bit) {
    if (!errors[size_t(bit)] || bit == 15) continue;
    if (kBits[bit].family == Family::kGentler) {
      gentler.push_back(bit);
      continue;
    }
    out.push_back(errorBit(bit, view));
  }
  if (!gentler.empty()) out.push_back(gentlerMessage(gentler));

  // Beyond a limit without the bit that says so (e.g. after Recover, before moving back).
  if (!errors[0] && !errors[7] && view.spec) {
    for (const JointExcursion& e : jointsBeyondLimits(live.state.q, live.dof, view.settings, *view.spec)) {
      out.push_back({tr("J%1 outside its range").arg(e.joint + 1), describe(e), remedy(e), {}, false});
    }
  }
  if (!errors[1] && !errors[8] && view.settings) {
    if (const auto box = tcpOutsideBox(live.state.toolTobase_pos_m, view.settings->box))
      out.push_back({tr("TCP outside the safety box"), describe(*box),
                     remedy(*box) + tr(" before the motors are switched on or a motion starts"), {}, false});
  }
  return out;
}

}  // namespace rci::ui::text
