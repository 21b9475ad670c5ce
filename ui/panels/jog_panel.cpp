// SPDX-License-Identifier: Apache-2.0
// Jog panel: the buttons and speed slider; the motion itself is in jog_motion (real-time side).
#include "panels/jog_panel.h"

#include <stdexcept>

#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

#include "panels/fields.h"
#include "panels/jog_motion.h"
#include "session/session.h"

namespace rci::ui {

using RCI::robot::StartMoveRequest;

JogPanel::JogPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("jog"), tr("Jog"), parent) {
  auto* speed_group = new QGroupBox(tr("Jog speed"), this);
  auto* speed_row = new QHBoxLayout(speed_group);
  speed_ = new QSlider(Qt::Horizontal, speed_group);
  speed_->setObjectName(QStringLiteral("jog.speed"));
  speed_->setRange(1, 100);
  speed_->setToolTip(tr("Jog speed in percent: 100 % is half the rated joint speed, 0.25 m/s or 0.5 rad/s"));
  speed_label_ = new QLabel(speed_group);
  speed_label_->setObjectName(QStringLiteral("jog.speedlabel"));
  speed_label_->setMinimumWidth(44);
  speed_label_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  speed_row->addWidget(speed_, 1);
  speed_row->addWidget(speed_label_);
  speed_->setValue(loadValue(QStringLiteral("speed"), 20).toInt());
  speed_label_->setText(QStringLiteral("%1 %").arg(speed_->value()));
  connect(speed_, &QSlider::valueChanged, this, [this](int v) {
    speed_label_->setText(QStringLiteral("%1 %").arg(v));
    saveValue(QStringLiteral("speed"), v);
  });
  body()->addWidget(speed_group);
  body()->addWidget(makeJointGroup());
  body()->addWidget(makeCartesianGroup());
  auto* hint = new QLabel(tr("Hold a button to move; release to stop. Motors must be on."), this);
  hint->setWordWrap(true);
  body()->addWidget(hint);
  showModel();
  // Motion results (GUI thread, queued by the session).
  connect(&session, &Session::motionFinished, this, [this](const QString& label, bool ok, const QString& message) {
    const QString prefix = title() + QStringLiteral(": ");
    if (!label.startsWith(prefix)) return;
    if (ok)
      showStatus(tr("jog %1 done.").arg(label.mid(prefix.size())), false);
    else
      showFailure(tr("jog %1").arg(label.mid(prefix.size())), message);
  });
}

JogPanel::~JogPanel() {
  if (active_) active_->stop.store(true);
}

QPushButton* JogPanel::makeJogButton(const QString& name, const QString& text, const QString& tip, bool cartesian,
                                     int axis, int direction, QWidget* parent) {
  auto* button = new QPushButton(text, parent);
  button->setObjectName(name);
  button->setToolTip(tip);
  button->setAutoRepeat(false);
  button->setMinimumWidth(44);
  addSendWidget(button);
  const QString what = tip;
  connect(button, &QPushButton::pressed, this,
          [this, cartesian, axis, direction, what] { press(cartesian, axis, direction, what); });
  connect(button, &QPushButton::released, this, &JogPanel::release);
  return button;
}

QWidget* JogPanel::makeJointGroup() {
  auto* group = new QGroupBox(tr("Joints"), this);
  auto* grid = new QGridLayout(group);
  for (int i = 0; i < 7; ++i) {
    auto* label = new QLabel(QStringLiteral("J%1").arg(i + 1), group);
    auto* minus = makeJogButton(QStringLiteral("jog.joint%1.minus").arg(i + 1), QStringLiteral("−"),
                                tr("J%1 \u2212").arg(i + 1), false, i, -1, group);
    auto* plus = makeJogButton(QStringLiteral("jog.joint%1.plus").arg(i + 1), QStringLiteral("+"),
                               tr("J%1 +").arg(i + 1), false, i, +1, group);
    auto* angle = new QLabel(group);
    angle->setObjectName(QStringLiteral("jog.joint%1.angle").arg(i + 1));
    angle->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    angle->setMinimumWidth(80);
    angle->setToolTip(tr("Measured position of joint %1").arg(i + 1));
    grid->addWidget(label, i, 0);
    grid->addWidget(minus, i, 1);
    grid->addWidget(plus, i, 2);
    grid->addWidget(angle, i, 3);
    joint_rows_[i] = {label, minus, plus, angle};
    angles_[i] = angle;
  }
  grid->setColumnStretch(4, 1);
  return group;
}

QWidget* JogPanel::makeCartesianGroup() {
  auto* group = new QGroupBox(tr("TCP (base frame)"), this);
  auto* grid = new QGridLayout(group);
  const char* axes[6] = {"x", "y", "z", "rx", "ry", "rz"};
  for (int i = 0; i < 6; ++i) {
    const QString axis = QLatin1String(axes[i]);
    const int row = i % 3, column = 3 * (i / 3);
    grid->addWidget(new QLabel(axis, group), row, column);
    grid->addWidget(makeJogButton(QStringLiteral("jog.cart.%1.minus").arg(axis), QStringLiteral("−"),
                                  tr("TCP %1 \u2212").arg(axis), true, i, -1, group),
                    row, column + 1);
    grid->addWidget(makeJogButton(QStringLiteral("jog.cart.%1.plus").arg(axis), QStringLiteral("+"),
                                  tr("TCP %1 +").arg(axis), true, i, +1, group),
                    row, column + 2);
  }
  return group;
}

double JogPanel::speedFraction() const { return speed_->value() / 100.0; }

void JogPanel::press(bool cartesian, int axis, int direction, const QString& what) {
  if (!isOpen()) return;
  if (active_) active_->held.store(false);  // a press without release (focus lost): end that jog
  auto flags = std::make_shared<JogFlags>();
  active_ = flags;
  const auto& model = spec();
  const OperatorSettings& o = session().operatorSettings();
  const JointLimitsRad limits = jogLimits(model, o.soft_limits_enabled, o.soft_lower_deg, o.soft_upper_deg);
  const double speed = speedFraction();
  showStatus(tr("jog %1 ...").arg(what), false);
  // The job runs on the session's motion worker; the callbacks on the client's real-time thread.
  // GUI -> real time: the atomics of JogFlags (shared_ptr keeps them alive for both sides).
  session().runMotion(title() + QStringLiteral(": ") + what, [=, &model](xmate::Robot& robot, const MotionToken& token) {
    // Stop requests end the jog; so does a window that stopped responding (dead-man: the GUI thread
    // did not tick for kJogDeadManMs, so a button release might go unseen) -- the jog ramps down.
    auto stop_watch = [flags, &token] {
      if (token.stopRequested()) flags->stop.store(true, std::memory_order_relaxed);
      if (token.windowSilenceMs() > kJogDeadManMs) {
        flags->held.store(false, std::memory_order_relaxed);
        flags->window_silent.store(true, std::memory_order_relaxed);
      }
    };
    if (cartesian) {
      CartesianJog jog(axis, direction, speed, model.dof, limits, *flags);
      robot.startMove(StartMoveRequest::ControllerMode::kCartesianPosition,
                      StartMoveRequest::MotionGeneratorMode::kCartesianPosition);
      robot.Control(xmate::CartesianControl([&jog, &stop_watch](RCI::robot::RobotState state) {
        stop_watch();
        return jog.next(state);
      }));
    } else {
      JointJog jog(model, axis, direction, speed, limits, *flags);
      robot.startMove(StartMoveRequest::ControllerMode::kJointPosition,
                      StartMoveRequest::MotionGeneratorMode::kJointPosition);
      robot.Control(xmate::JointControl([&jog, &stop_watch](RCI::robot::RobotState state) {
        stop_watch();
        return jog.next(state);
      }));
    }
    if (flags->window_silent.load())
      throw std::runtime_error("the jog stopped because the window did not respond for more than 150 ms (it could "
                               "not have seen the button's release); press and hold the button again");
  });
}

void JogPanel::release() {
  if (active_) active_->held.store(false);
}

// Dead-man behaviour: a jog never outlives the operator's attention (window deactivated, panel
// hidden), even if the button's release never arrives.
void JogPanel::changeEvent(QEvent* event) {
  if (event->type() == QEvent::ActivationChange && !isActiveWindow()) release();
  PanelBase::changeEvent(event);
}

void JogPanel::hideEvent(QHideEvent* event) {
  release();
  PanelBase::hideEvent(event);
}

void JogPanel::showModel() {
  for (int i = 0; i < 7; ++i)
    for (auto* w : joint_rows_[i]) w->setVisible(i < dof());
}

void JogPanel::sessionOpened() { showModel(); }

void JogPanel::refresh(const LiveState& live) {
  if (!live.has_state) return;
  for (int i = 0; i < live.dof && i < 7; ++i)
    angles_[i]->setText(QStringLiteral("%1 deg").arg(live.state.q[i] * kDegPerRad, 0, 'f', 2));
}

void JogPanel::sessionClosed() {
  if (active_) active_->stop.store(true);
  active_.reset();
  for (auto* angle : angles_) angle->clear();
}

}  // namespace rci::ui
