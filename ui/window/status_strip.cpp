// SPDX-License-Identifier: Apache-2.0
// The status bar fields (status_strip.h).
#include "window/status_strip.h"

#include <QFrame>
#include <QLabel>
#include <QStatusBar>

#include <algorithm>

#include "rsi/session_monitor.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {
namespace {

const char* const kNormal = "";
const char* const kGood = "color: #1b7a2e;";
const char* const kBad = "color: #c62828; font-weight: 600;";
const char* const kWarn = "color: #b26a00;";

void setField(QLabel* label, const QString& text, const char* style) {
  label->setText(text);
  const QString sheet = QString::fromLatin1(style);
  if (label->styleSheet() != sheet) label->setStyleSheet(sheet);
}

// The active error bits by their plain titles; the enum names for the tooltip.
QStringList activeErrorTitles(const RCI::robot::RobotState& state) {
  QStringList titles;
  for (int bit = 0; bit < text::kErrorBitCount; ++bit)
    if (state.errors[size_t(bit)]) titles << text::errorBitTitle(bit);
  return titles;
}

void showRealtime(QLabel* label, const xmate::net::RealtimeStatus& realtime) {
  const bool fifo = realtime.fifo;
  setField(label, fifo ? StatusStrip::tr("RT: SCHED_FIFO %1").arg(realtime.priority) : StatusStrip::tr("RT: normal priority"),
           fifo ? kGood : kWarn);
  label->setToolTip(fifo ? QString::fromStdString(realtime.describe())
                         : StatusStrip::tr("The client's real-time thread runs at normal priority: %1")
                               .arg(QString::fromStdString(realtime.reason)));
}

}  // namespace

QString robotModeText(RCI::robot::RobotMode mode) { return text::robotMode(mode); }

StatusStrip::StatusStrip(Session& session, QStatusBar* bar) : QObject(bar), session_(session), bar_(bar) {
  target_ = field("status.target", tr("What this window is connected to"));
  mode_ = field("status.mode", tr("What the robot is doing, as its controller reports it"));
  motors_ = field("status.motors", tr("Motor power as reported by the controller"));
  rsi_ = field("status.rsi", QString());
  cycle_ = field("status.cycle", tr("How often the robot sends its RSI datagram and waits for this PC's answer"));
  late_ = field("status.late", QString());
  answer_ = field("status.answer", tr("99th percentile of the time this PC took to answer the robot, over the last "
                                      "250 cycles; it must stay well below the cycle"));
  realtime_ = field("status.realtime", QString());
  rate_ = field("status.rate", tr("States received per second (nominal 1000 Hz)"));
  jitter_ = field("status.jitter", tr("99th percentile of |period - 1 ms| between received states"));
  success_ = field("status.success", tr("Share of the last 100 motion commands that reached the controller in time"));
  sensor_ = field("status.sensor", QString());
  errors_ = field("status.errors", QString());
  xmate_fields_ = {mode_, motors_, rate_, jitter_, success_};
  rsi_fields_ = {rsi_, cycle_, late_, answer_, sensor_};
  showFamily(false);
  refresh();
}

void StatusStrip::showField(QLabel* label, bool shown) {
  label->setVisible(shown);
  if (auto* rule = bar_->findChild<QFrame*>(label->objectName() + QStringLiteral(".rule"))) rule->setVisible(shown);
}

void StatusStrip::showFamily(bool rsi) {
  if (family_shown_ == int(rsi)) return;
  family_shown_ = int(rsi);
  for (QLabel* label : xmate_fields_) showField(label, !rsi);
  for (QLabel* label : rsi_fields_) showField(label, rsi);
  if (rsi) showField(errors_, false);  // the xMate's error bits; refreshOpen shows them when there are some
}

// Each field after the first is separated from the previous one by a thin vertical rule.
QLabel* StatusStrip::field(const char* name, const QString& tooltip) {
  if (target_ != nullptr) {  // target_ is the first field
    auto* rule = new QFrame(bar_);
    rule->setObjectName(QString::fromLatin1(name) + QStringLiteral(".rule"));
    rule->setFrameShape(QFrame::VLine);
    rule->setFrameShadow(QFrame::Sunken);
    bar_->addPermanentWidget(rule);
  }
  auto* label = new QLabel(bar_);
  label->setContentsMargins(6, 0, 6, 0);
  label->setObjectName(QString::fromLatin1(name));
  label->setToolTip(tooltip);
  bar_->addPermanentWidget(label);
  return label;
}

void StatusStrip::showConnecting() {
  setField(target_, tr("Connecting to %1 …").arg(session_.target().describe()), kWarn);
}

void StatusStrip::refresh() {
  if (session_.isOpen()) {
    refreshOpen();
  } else if (!session_.isOpening()) {
    refreshClosed();
  }
}

void StatusStrip::refreshClosed() {
  showFamily(false);
  setField(target_, tr("Not connected"), kBad);
  for (QLabel* label : {mode_, motors_, realtime_, rate_, jitter_, success_, errors_}) label->clear();
  for (QLabel* label : rsi_fields_) label->clear();
  realtime_->setToolTip(QString());
  errors_->setVisible(false);
  errorsRule()->setVisible(false);
}

QFrame* StatusStrip::errorsRule() const { return bar_->findChild<QFrame*>(QStringLiteral("status.errors.rule")); }

void StatusStrip::refreshOpen() {
  const LiveState& live = session_.live();
  if (session_.isReconnecting()) {
    setField(target_, tr("%1 — reconnecting …").arg(session_.target().describe()), kBad);
    return;
  }
  setField(target_, session_.target().describe(), kNormal);
  if (session_.rsiArm() != nullptr) {
    refreshRsi();
    return;
  }
  showFamily(false);
  if (!live.has_state) {
    setField(mode_, tr("Waiting for the first state …"), kWarn);
    return;
  }
  const RCI::robot::RobotState& state = live.state;
  const bool reflex = state.robot_mode == RCI::robot::RobotMode::kReflex;
  if (live.stopping) {
    // Motions wait for the arm to stand still; the buttons that start one are disabled meanwhile.
    setField(mode_, tr("Mode: %1 · stopping …").arg(robotModeText(state.robot_mode)), kWarn);
    mode_->setToolTip(tr("The arm is coming to rest (joint %1 at %2 deg/s). Motions can start once it stands still.")
                          .arg(live.standstill.fastest_joint + 1)
                          .arg(live.standstill.fastest_speed * 180.0 / 3.14159265358979323846, 0, 'f', 1));
  } else {
    setField(mode_, tr("Mode: %1").arg(robotModeText(state.robot_mode)), reflex ? kBad : kNormal);
    mode_->setToolTip(tr("What the robot is doing, as its controller reports it"));
  }
  setField(motors_, live.motor_state == 1 ? tr("Motors on") : tr("Motors off"), live.motor_state == 1 ? kGood : kNormal);

  showRealtime(realtime_, live.realtime);

  setField(rate_, tr("%1 Hz").arg(live.loop_rate_hz, 0, 'f', 0), live.loop_rate_hz < 900 && live.loop_rate_hz > 0 ? kWarn : kNormal);
  setField(jitter_, tr("Jitter p99 %1 µs").arg(live.timing.period.jitter_p99_us, 0, 'f', 0), kNormal);
  const bool moving = live.motion_running || state.robot_mode == RCI::robot::RobotMode::kMove;
  if (moving) {
    const double percent = state.control_command_success_rate * 100.0;
    setField(success_, tr("Commands %1 %").arg(percent, 0, 'f', 0), percent < 95 ? kBad : kNormal);
  } else {
    setField(success_, tr("Commands –"), kNormal);
  }

  const QStringList errors = activeErrorTitles(state);
  errors_->setVisible(!errors.isEmpty() || live.safety_stop != 1);
  errorsRule()->setVisible(errors_->isVisibleTo(bar_));
  QString shown;
  if (live.safety_stop == 2) shown = tr("EMERGENCY STOP");
  if (live.safety_stop == 3) shown = tr("GUARD STOP");
  if (!errors.isEmpty()) shown += (shown.isEmpty() ? QString() : QStringLiteral("  ")) + tr("Errors: %1").arg(errors.join(", "));
  setField(errors_, shown, kBad);
  errors_->setToolTip(errors_->isVisibleTo(bar_) ? problemsTip() : QString());
}

// A KUKA over RSI: what the RSI session does, how fast and how well this PC answers, the sensor.
void StatusStrip::refreshRsi() {
  showFamily(true);
  const LiveState& live = session_.live();
  const xmate::rsi::SessionStatus& rsi = live.rsi;
  switch (rsi.phase) {
    case xmate::rsi::SessionPhase::kWaiting:
      setField(rsi_, tr("Waiting for the robot"), kWarn);
      break;
    case xmate::rsi::SessionPhase::kRunning:
      setField(rsi_, tr("RSI running"), kGood);
      break;
    case xmate::rsi::SessionPhase::kStopped:
      setField(rsi_, rsi.cause == xmate::rsi::StopCause::kTimeout ? tr("RSI stopped: too many late answers")
                                                                 : tr("RSI stopped by the controller"),
               kBad);
      break;
  }
  rsi_->setToolTip(QString::fromStdString(xmate::rsi::describe(rsi)));

  if (rsi.cycle_ms > 0) setField(cycle_, tr("Cycle %1 ms").arg(rsi.cycle_ms), kNormal);
  else setField(cycle_, tr("Cycle –"), kNormal);

  // Late answers in a row run up to the context's Timeout, where the robot stops RSI.
  const char* late_style = rsi.late_in_a_row >= std::max(1, rsi.timeout / 2) ? kBad
                           : rsi.late_in_a_row > 0                         ? kWarn
                                                                           : kNormal;
  setField(late_, tr("Late answers %1 (robot) · %2 (PC)").arg(rsi.delay, 0, 'f', 0).arg(rsi.late_answers), late_style);
  late_->setToolTip(tr("Answers the robot counted late in this RSI session (its Delay: %1; %2 in a row, it stops "
                       "RSI at %3), and answers this PC sent later than a cycle (%4)")
                        .arg(rsi.delay, 0, 'f', 0)
                        .arg(rsi.late_in_a_row)
                        .arg(rsi.timeout)
                        .arg(rsi.late_answers));

  if (rsi.answer_p99_ms > 0) {
    const double cycle = rsi.cycle_ms > 0 ? rsi.cycle_ms : 4;
    const char* style = rsi.answer_p99_ms >= cycle ? kBad : rsi.answer_p99_ms >= cycle / 2 ? kWarn : kNormal;
    setField(answer_, tr("Answer p99 %1 ms").arg(rsi.answer_p99_ms, 0, 'f', 2), style);
  } else {
    setField(answer_, tr("Answer p99 –"), kNormal);
  }

  showRealtime(realtime_, live.realtime);

  if (!live.has_force_sensor) {
    setField(sensor_, tr("No F/T sensor"), kNormal);
    sensor_->setToolTip(tr("No force/torque sensor is configured: hand guiding is not available"));
  } else if (live.force_reading) {
    setField(sensor_, tr("F/T sensor OK"), kGood);
    sensor_->setToolTip(tr("The force/torque sensor sends healthy readings"));
  } else {
    setField(sensor_, tr("F/T sensor: no reading"), kBad);
    sensor_->setToolTip(tr("The force/torque sensor sends no recent healthy reading: check its cable, power and "
                           "address (hand guiding stops without it)"));
  }
}

// Every active problem in operator words, what to do, and the enum names as the detail.
QString StatusStrip::problemsTip() const {
  QStringList lines;
  QStringList details;
  for (const text::OperatorMessage& m : text::activeProblems(text::viewOf(session_))) {
    lines << m.line();
    if (!m.detail.isEmpty()) details << m.detail;
  }
  if (lines.isEmpty()) return QString();
  QString tip = lines.join(QStringLiteral("\n\n")) + tr("\n\nThe Safety panel shows the same, with Recover.");
  if (!details.isEmpty()) tip += QStringLiteral("\n\n(%1)").arg(details.join(QStringLiteral(", ")));
  return tip;
}

}  // namespace rci::ui
