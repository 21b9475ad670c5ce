// SPDX-License-Identifier: Apache-2.0
// Force-guide panel: runs guide::AdmittanceGuide on the session's arm through Session::runArmMotion,
// bounded by the RSI correction limits, and shows its status on each display tick.
#include "panels/force_guide_panel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "arm/arm.h"
#include "guide/admittance.h"
#include "guide/ft_source.h"
#include "model/arm_kinematics.h"
#include "panels/fields.h"
#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {

using xmate::guide::GuideAxes;
using xmate::guide::GuideEnd;
using xmate::guide::GuideStatus;

// The guide reads the sensor through `source`, which must outlive it: they live and die together.
struct ForceGuide {
  ForceGuide(const xmate::ft::NetFtClient& sensor, const xmate::model::RobotSpec& spec, double cycle_s,
             const xmate::guide::GuideParameters& parameters, const xmate::guide::ToolWeight& tool)
      : source(sensor), guide(xmate::model::ArmKinematics(spec), source, cycle_s, parameters, tool) {}
  const xmate::guide::NetFtSource source;
  xmate::guide::AdmittanceGuide guide;
};

namespace {

// The guide, brought to a smooth stop when the session's token asks (Stop motion, disconnect).
class GuideUntilStopped : public xmate::arm::JointMotion {
 public:
  GuideUntilStopped(xmate::guide::AdmittanceGuide& guide, const MotionToken& token) : guide_(guide), token_(token) {}
  bool command(const xmate::arm::ArmSample& now, std::array<double, 7>& q) override {
    if (token_.stopRequested()) guide_.requestStop();
    return guide_.command(now, q);
  }

 private:
  xmate::guide::AdmittanceGuide& guide_;
  const MotionToken& token_;
};

const QString kMotionLabel = QStringLiteral("Hand guiding: guide");

}  // namespace

ForceGuidePanel::ForceGuidePanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("guide"), tr("Hand guiding"), parent) {
  auto* how = new QGroupBox(tr("Guide by the force sensor"), this);
  auto* form = new QFormLayout(how);
  axes_ = new QComboBox(how);
  axes_->setObjectName(QStringLiteral("guide.axes"));
  axes_->addItem(tr("Translation only"), int(GuideAxes::kTranslation));
  axes_->addItem(tr("Rotation only"), int(GuideAxes::kRotation));
  axes_->addItem(tr("Free"), int(GuideAxes::kFree));
  axes_->setToolTip(tr("Translation: your push moves the tool, its orientation is held. Rotation: your twist turns "
                       "the tool about the flange, its position is held. Free: both"));
  form->addRow(tr("Guide"), axes_);

  const xmate::guide::GuideParameters defaults;
  mass_ = makeNumberField(QStringLiteral("guide.mass"), 1, 50, 1, tr(" kg"),
                          tr("Virtual mass: heavier feels steadier, lighter follows quicker"), how);
  damping_ = makeNumberField(QStringLiteral("guide.damping"), 20, 600, 0, tr(" N·s/m"),
                             tr("Virtual damping: more makes the arm slow down sooner when you let go"), how);
  speed_ = makeNumberField(QStringLiteral("guide.speed"), 10, 250, 0, tr(" mm/s"),
                           tr("The flange never moves faster than this while guided"), how);
  dead_band_ = makeNumberField(QStringLiteral("guide.deadBand"), 0.5, 30, 1, tr(" N"),
                               tr("Forces below this are ignored (sensor noise, a light touch)"), how);
  mass_->setValue(defaults.mass);
  damping_->setValue(defaults.damping);
  speed_->setValue(defaults.max_speed * 1e3);
  dead_band_->setValue(defaults.force_dead_band);
  form->addRow(tr("Mass"), mass_);
  form->addRow(tr("Damping"), damping_);
  form->addRow(tr("Top speed"), speed_);
  form->addRow(tr("Dead band"), dead_band_);

  tool_mass_ = makeNumberField(QStringLiteral("guide.toolMass"), 0, 30, 2, tr(" kg"),
                               tr("The tool hanging on the sensor: its weight is removed at every pose"), how);
  form->addRow(tr("Tool mass"), tool_mass_);
  auto* center_label = new QLabel(tr("Tool centre of mass: x, y, z in mm, flange frame"), how);
  center_label->setWordWrap(true);
  form->addRow(center_label);
  auto* center_row = new QHBoxLayout;
  for (const char* axis : {"x", "y", "z"}) {
    auto* field = makeNumberField(QStringLiteral("guide.toolCenter.%1").arg(QLatin1String(axis)), -500, 500, 0,
                                  QString(), tr("The tool's centre of mass in the flange frame (%1)").arg(QLatin1String(axis)),
                                  how);
    tool_center_.push_back(field);
    center_row->addWidget(field);
  }
  form->addRow(center_row);
  body()->addWidget(how);

  auto* state_box = new QGroupBox(tr("State"), this);
  auto* state_form = new QFormLayout(state_box);
  auto* state_row = new QHBoxLayout;
  lamp_ = new Lamp(lampAmber(), state_box);
  lamp_->setObjectName(QStringLiteral("guide.lamp"));
  lamp_->setToolTip(tr("On while the arm follows your hand"));
  state_ = new QLabel(tr("Not guiding"), state_box);
  state_->setObjectName(QStringLiteral("guide.state"));
  state_->setWordWrap(true);
  state_row->addWidget(lamp_);
  state_row->addWidget(state_, 1);
  state_form->addRow(state_row);
  detail_ = new QLabel(state_box);
  detail_->setObjectName(QStringLiteral("guide.detail"));
  detail_->setWordWrap(true);
  state_form->addRow(detail_);
  message_ = new MessageLine(QStringLiteral("guide.message"), state_box);
  state_form->addRow(message_);
  auto* buttons = new QHBoxLayout;
  start_ = new QPushButton(tr("Start guiding"), state_box);
  start_->setObjectName(QStringLiteral("guide.start"));
  start_->setToolTip(tr("Start with nobody touching the tool: the sensor's reading now counts as zero"));
  stop_ = new QPushButton(tr("Stop guiding"), state_box);
  stop_->setObjectName(QStringLiteral("guide.stop"));
  stop_->setToolTip(tr("The arm slows down to a stop and holds"));
  start_->setEnabled(false);  // refresh(): while connected and no motion runs
  buttons->addStretch(1);
  buttons->addWidget(start_);
  buttons->addWidget(stop_);
  state_form->addRow(buttons);
  body()->addWidget(state_box);

  loadFields({mass_, damping_, speed_, dead_band_, tool_mass_});
  loadFields(tool_center_);
  axes_->setCurrentIndex(std::max(0, axes_->findData(loadValue(QStringLiteral("axes"), int(GuideAxes::kTranslation)))));

  connect(start_, &QPushButton::clicked, this, &ForceGuidePanel::start);
  connect(stop_, &QPushButton::clicked, this, &ForceGuidePanel::stop);
  connect(&session, &Session::motionFinished, this, [this](const QString& label, bool ok, const QString& message) {
    if (label != kMotionLabel) return;
    guiding_ = false;
    showGuideStatus();
    updateButtons();
    if (!ok) showFailure(tr("Hand guiding"), message);
  });
  connect(&session, &Session::commandFinished, this, [this](const QString& label, bool ok, const QString& message) {
    if (label != kMotionLabel || ok) return;
    guiding_ = false;  // refused to start (another motion runs, not connected)
    showGuideStatus();
    updateButtons();
    showFailure(tr("Hand guiding"), message);
  });
}

ForceGuidePanel::~ForceGuidePanel() = default;

bool ForceGuidePanel::appliesTo(Session& session) const { return session.forceSensor() != nullptr; }

void ForceGuidePanel::start() {
  const xmate::ft::NetFtClient* sensor = session().forceSensor();
  xmate::arm::Arm* arm = session().arm();
  if (sensor == nullptr || arm == nullptr) {
    message_->showError(tr("Connect to a KUKA with its force sensor first."));
    return;
  }
  if (guiding_ || session().live().motion_running) {
    message_->showError(tr("Another motion is running: stop it first (Stop guiding, or Stop motion in the toolbar)."));
    return;
  }
  if (!session().live().force_reading) {
    message_->showError(tr("No reading from the force sensor: check its cable and power (Force sensor panel), "
                           "then press Start guiding again."));
    return;
  }
  xmate::guide::GuideParameters parameters;
  parameters.axes = GuideAxes(axes_->currentData().toInt());
  parameters.mass = mass_->value();
  parameters.damping = damping_->value();
  parameters.max_speed = speed_->value() * 1e-3;
  parameters.force_dead_band = dead_band_->value();
  xmate::guide::ToolWeight tool{tool_mass_->value(),
                                {tool_center_[0]->value() * 1e-3, tool_center_[1]->value() * 1e-3,
                                 tool_center_[2]->value() * 1e-3}};
  saveFields({mass_, damping_, speed_, dead_band_, tool_mass_});
  saveFields(tool_center_);
  saveValue(QStringLiteral("axes"), axes_->currentData());

  auto guide = std::make_shared<ForceGuide>(*sensor, arm->spec(), arm->cycleSeconds(), parameters, tool);
  if (xmate::arm::has(arm->capabilities(), xmate::arm::Capability::kCorrectionLimits)) {
    try {  // within the correction limits around the RSI start pose
      const xmate::arm::MotionBounds bounds = arm->motionBounds();
      guide->guide.setJointBounds(bounds.lower, bounds.upper);
    } catch (const std::runtime_error&) {  // RSI not running yet: the motion itself will say so
    }
  }
  guide_ = guide;
  guiding_ = true;
  message_->clearMessage();
  session().runArmMotion(kMotionLabel, [guide](xmate::arm::Arm& a, const MotionToken& token) {
    GuideUntilStopped motion(guide->guide, token);
    a.runJointMotion(motion);
  });
  showGuideStatus();
  updateButtons();
}

void ForceGuidePanel::stop() {
  if (guide_ && guiding_) guide_->guide.requestStop();
}

void ForceGuidePanel::showGuideStatus() {
  if (!guide_) {
    lamp_->setOn(false);
    state_->setText(tr("Not guiding"));
    detail_->clear();
    return;
  }
  const GuideStatus s = guide_->guide.status();
  lamp_->setOn(guiding_ && s.cycles > 0 && s.end == GuideEnd::kRunning);  // on once the bias is taken
  if (guiding_ && s.cycles == 0) {
    state_->setText(tr("Starting: waiting for the robot's first cycle …"));
  } else if (guiding_ && s.end == GuideEnd::kRunning) {
    state_->setText(tr("Guiding: push or twist the tool to move it; Stop guiding when done"));
  } else {
    state_->setText(s.end == GuideEnd::kRunning ? tr("Not guiding")
                                                : tr("Guiding ended: %1").arg(QString::fromUtf8(xmate::guide::describe(s.end))));
  }
  if (!guiding_) {
    detail_->clear();
    return;
  }
  const double force = std::hypot(s.wrench[0], s.wrench[1], s.wrench[2]);
  const double torque = std::hypot(s.wrench[3], s.wrench[4], s.wrench[5]);
  const double speed = 1e3 * std::hypot(s.velocity[0], s.velocity[1], s.velocity[2]);
  QString text = tr("Force %1 N, torque %2 Nm, speed %3 mm/s")
                     .arg(force, 0, 'f', 1)
                     .arg(torque, 0, 'f', 2)
                     .arg(speed, 0, 'f', 0);
  if (s.cannot_follow)
    text += tr("\nThe arm cannot move that way here (edge of its reach): push it back the way it came.");
  else if (s.limited_axis >= 0)
    text += tr("\nA%1 is held at the edge of the range it may move in (RSI correction limit or axis range).")
                .arg(s.limited_axis + 1);
  detail_->setText(text);
}

void ForceGuidePanel::updateButtons() {
  const bool running = isOpen() && session().live().motion_running;
  start_->setEnabled(isOpen() && !guiding_ && !running);
  stop_->setEnabled(guiding_ && running);
}

void ForceGuidePanel::refresh(const LiveState&) {
  updateButtons();
  showGuideStatus();
}

void ForceGuidePanel::sessionOpened() { updateButtons(); }

void ForceGuidePanel::sessionClosed() {
  guiding_ = false;
  updateButtons();
  guide_.reset();
  showGuideStatus();
  state_->setText(tr("Not connected"));
}

}  // namespace rci::ui
