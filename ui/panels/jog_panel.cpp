// SPDX-License-Identifier: Apache-2.0
// Jog panel: the buttons and speed slider; the motion itself is in core's jog (real-time side).
#include "panels/jog_panel.h"

#include <stdexcept>

#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

#include "jog/jog.h"
#include "panels/fields.h"
#include "model/arm_kinematics.h"
#include "session/session.h"

namespace rci::ui {

using namespace xmate::jog;

namespace {

// The axis as the robot's maker names it: J1.. on an xMate, A1.. on a KUKA.
QString axisName(const xmate::model::RobotSpec& spec, int i) {
  return (spec.family == xmate::model::RobotFamily::kKuka ? QStringLiteral("A%1") : QStringLiteral("J%1")).arg(i + 1);
}

// Each cycle on the controller's real-time thread: stop requests end the jog; so does a window that
// stopped responding (dead-man: the GUI thread did not tick for kJogDeadManMs, so a button release
// might go unseen) -- the jog ramps down. Lock-free.
void watchStop(JogFlags& flags, const MotionToken& token) {
  if (token.stopRequested()) flags.stop.store(true, std::memory_order_relaxed);
  if (token.windowSilenceMs() > kJogDeadManMs) {
    flags.held.store(false, std::memory_order_relaxed);
    flags.window_silent.store(true, std::memory_order_relaxed);
  }
}

const char* const kWindowSilent =
    "the jog stopped because the window did not respond for more than 150 ms (it could not have seen the button's "
    "release); press and hold the button again";

}  // namespace

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
  hint_ = new QLabel(tr("Hold a button to move; release to stop. Motors must be on."), this);
  hint_->setObjectName(QStringLiteral("jog.hint"));
  hint_->setWordWrap(true);
  body()->addWidget(hint_);
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
  addMotionWidget(button);
  // The tooltip names the axis as the open robot's maker does (showModel()).
  connect(button, &QPushButton::pressed, this,
          [this, button, cartesian, axis, direction] { press(cartesian, axis, direction, button->toolTip()); });
  connect(button, &QPushButton::released, this, &JogPanel::release);
  return button;
}

QWidget* JogPanel::makeJointGroup() {
  auto* group = new QGroupBox(tr("Joints"), this);
  auto* grid = new QGridLayout(group);
  for (int i = 0; i < 7; ++i) {
    auto* label = new QLabel(QStringLiteral("J%1").arg(i + 1), group);
    joint_names_[i] = label;
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
  group->setObjectName(QStringLiteral("jog.cart"));
  cartesian_group_ = group;
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
  xmate::arm::Arm* open_arm = session().arm();
  if (!open_arm) return;
  if (active_) active_->held.store(false);  // a press without release (focus lost): end that jog
  auto flags = std::make_shared<JogFlags>();
  active_ = flags;
  const auto& model = spec();
  const OperatorSettings& o = session().operatorSettings();
  const JointLimitsRad limits = jogLimits(model, o.soft_limits_enabled, o.soft_lower_deg, o.soft_upper_deg);
  const double speed = speedFraction();
  const QString label = title() + QStringLiteral(": ") + what;
  showStatus(tr("jog %1 ...").arg(what), false);
  // The job runs on the session's motion worker; the motions' command() on the arm's real-time
  // thread. GUI -> real time: the atomics of JogFlags (shared_ptr keeps them alive for both sides).
  session().runArmMotion(label, [=, &model](xmate::arm::Arm& arm, const MotionToken& token) {
    // Within what the arm can reach now: on RSI, the context's correction limits around where it
    // was switched on -- the jog brakes before them.
    const xmate::arm::MotionBounds bounds = arm.motionBounds();
    const JointLimitsRad within = withinBounds(limits, bounds, model.dof);
    std::function<void()> stop_watch = [flags, &token] { watchStop(*flags, token); };
    const xmate::arm::Capabilities caps = arm.capabilities();
    if (cartesian && xmate::arm::has(caps, xmate::arm::Capability::kCartesianMotion)) {
      CartesianJog jog(axis, direction, speed, model.dof, within, *flags);
      CartesianJogMotion motion(jog, stop_watch);
      arm.runCartesianMotion(motion);
    } else if (cartesian) {
      const xmate::guide::GuideParameters parameters = cartesianJogParameters(axis, speed);
      const JogPush push(arm, axis, direction, parameters);
      xmate::guide::AdmittanceGuide guide(xmate::model::ArmKinematics(model), push, arm.cycleSeconds(), parameters);
      guide.setJointBounds(within.lower, within.upper);
      GuidedCartesianJogMotion motion(guide, *flags, stop_watch);
      arm.runJointMotion(motion);
    } else {
      JointJog jog(model, axis, direction, speed, within, *flags, arm.cycleSeconds());
      JointJogMotion motion(jog, stop_watch, bounds.session);
      arm.runJointMotion(motion);
      if (motion.sessionChanged())
        throw std::runtime_error("RSI was switched on again just as the jog started (a new RSI session); press and "
                                 "hold the button again");
    }
    if (flags->window_silent.load()) throw std::runtime_error(kWindowSilent);
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
  const auto& model = spec();
  for (int i = 0; i < 7; ++i) {
    for (auto* w : joint_rows_[i]) w->setVisible(i < dof());
    const QString name = axisName(model, i);
    joint_names_[i]->setText(name);
    if (auto* minus = qobject_cast<QPushButton*>(joint_rows_[i].value(1))) minus->setToolTip(tr("%1 \u2212").arg(name));
    if (auto* plus = qobject_cast<QPushButton*>(joint_rows_[i].value(2))) plus->setToolTip(tr("%1 +").arg(name));
    angles_[i]->setToolTip(tr("Measured position of axis %1").arg(name));
  }
}

void JogPanel::sessionOpened() {
  showModel();
  // The Cartesian jog streams poses to the xMate's Cartesian control; on other arms it moves the
  // flange (there is no tool on a KUKA over RSI) through the joints.
  const xmate::arm::Capabilities caps = session().arm() ? session().arm()->capabilities() : 0;
  cartesian_group_->setToolTip(xmate::arm::has(caps, xmate::arm::Capability::kCartesianMotion) ? QString()
                                                 : tr("Moves the flange along or about a base axis; it holds where an "
                                                      "axis reaches the range RSI allows or the arm its reach."));
  QString hint = tr("Hold a button to move; release to stop.");
  if (xmate::arm::has(caps, xmate::arm::Capability::kPowerControl)) hint += tr(" Motors must be on.");
  if (xmate::arm::has(caps, xmate::arm::Capability::kCorrectionLimits))
    hint += tr(" The robot's program must have RSI on; each axis moves only as far from where RSI was switched on "
               "as the RSI context allows, and the jog stops 1 deg before that.");
  hint_->setText(hint);
}

void JogPanel::refresh(const LiveState& live) {
  if (!live.has_arm_state) return;
  for (int i = 0; i < live.dof && i < 7; ++i)
    angles_[i]->setText(QStringLiteral("%1 deg").arg(live.arm.sample.q[size_t(i)] * kDegPerRad, 0, 'f', 2));
}

void JogPanel::sessionClosed() {
  if (active_) active_->stop.store(true);
  active_.reset();
  for (auto* angle : angles_) angle->clear();
}

}  // namespace rci::ui
