// SPDX-License-Identifier: Apache-2.0
// Soft limits panel: validated limits (parameter_checks) sent by setJointLimit, then recorded.
// "Disabled" sends the hardware range, so the controller's soft limits no longer restrict.
#include "panels/soft_limits_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <algorithm>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

SoftLimitsPanel::SoftLimitsPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("limits"), tr("Soft limits"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  auto* group = new QGroupBox(tr("Soft joint limits"), this);
  auto* grid = new QGridLayout(group);
  grid->addWidget(new QLabel(tr("Joint"), group), 0, 0);
  grid->addWidget(new QLabel(tr("Lower"), group), 0, 1);
  grid->addWidget(new QLabel(tr("Upper"), group), 0, 2);
  for (int i = 0; i < 7; ++i) {
    names_[i] = new QLabel(QStringLiteral("J%1").arg(i + 1), group);
    auto* lower = makeNumberField(QStringLiteral("limits.lower%1").arg(i + 1), -720, 720, 2, QStringLiteral("deg"),
                                  QString(), group);
    auto* upper = makeNumberField(QStringLiteral("limits.upper%1").arg(i + 1), -720, 720, 2, QStringLiteral("deg"),
                                  QString(), group);
    grid->addWidget(names_[i], i + 1, 0);
    grid->addWidget(lower, i + 1, 1);
    grid->addWidget(upper, i + 1, 2);
    lower_.append(lower);
    upper_.append(upper);
  }
  enabled_ = new QCheckBox(tr("Enabled"), group);
  enabled_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  enabled_->setObjectName(QStringLiteral("limits.enable"));
  enabled_->setToolTip(tr("Off sends the hardware range: only the hardware limits apply"));
  auto_limit_ = new QCheckBox(tr("Auto-limit"), group);
  auto_limit_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  auto_limit_->setObjectName(QStringLiteral("limits.auto"));
  auto_limit_->setToolTip(tr("Brake joints smoothly to a stop at the soft limit instead of stopping the motion "
                             "with an error (setJointLimit auto_limit)"));
  grid->addWidget(enabled_, 8, 1);
  grid->addWidget(auto_limit_, 8, 2);
  message_ = new MessageLine(QStringLiteral("limits.message"), group);
  grid->addWidget(message_, 9, 0, 1, 3);
  auto* row = new QHBoxLayout;
  auto* hardware = new QPushButton(tr("Hardware range"), group);
  hardware->setObjectName(QStringLiteral("limits.hardware"));
  hardware->setToolTip(tr("Fill the fields with the model's hardware limits"));
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("limits.apply"));
  apply->setToolTip(tr("Send the limits to the robot. A joint outside the new range is reported beyond its limit: "
                          "press Recover in the Safety panel, then jog or guide it back in"));
  addSendWidget(apply);
  row->addWidget(hardware);
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, 10, 0, 1, 3);
  body()->addWidget(group);

  resetToHardware();
  loadFields(lower_ + upper_);
  showModel();
  enabled_->setChecked(loadValue(QStringLiteral("enabled"), false).toBool());
  auto_limit_->setChecked(loadValue(QStringLiteral("auto_limit"), false).toBool());
  connect(hardware, &QPushButton::clicked, this, &SoftLimitsPanel::resetToHardware);
  connect(apply, &QPushButton::clicked, this, &SoftLimitsPanel::apply);
}

void SoftLimitsPanel::showModel() {
  const auto& s = spec();
  for (int i = 0; i < 7; ++i) {
    const bool used = i < s.dof;
    names_[i]->setVisible(used);
    lower_[i]->setVisible(used);
    upper_[i]->setVisible(used);
    if (used) {  // another model may have a smaller range
      upper_[i]->setValue(std::clamp(upper_[i]->value(), s.q_min[i] * kDegPerRad, s.q_max[i] * kDegPerRad));
      lower_[i]->setValue(std::clamp(lower_[i]->value(), s.q_min[i] * kDegPerRad, s.q_max[i] * kDegPerRad));
    }
    const QString range = tr("hardware range of joint %1: %2 to %3 deg")
                              .arg(i + 1)
                              .arg(s.q_min[i] * kDegPerRad, 0, 'f', 1)
                              .arg(s.q_max[i] * kDegPerRad, 0, 'f', 1);
    lower_[i]->setToolTip(tr("Lower soft limit; within the %1, below the upper limit").arg(range));
    upper_[i]->setToolTip(tr("Upper soft limit; within the %1, above the lower limit").arg(range));
  }
}

void SoftLimitsPanel::sessionOpened() { showModel(); }

void SoftLimitsPanel::resetToHardware() {
  const auto& s = spec();
  for (int i = 0; i < 7; ++i) {
    lower_[i]->setValue(s.q_min[i] * kDegPerRad);
    upper_[i]->setValue(s.q_max[i] * kDegPerRad);
  }
}

void SoftLimitsPanel::apply() {
  clearInvalid(lower_ + upper_);
  const auto& s = spec();
  const bool enabled = enabled_->isChecked();
  const bool auto_limit = auto_limit_->isChecked();
  std::array<double, 7> upper{}, lower{};
  for (int i = 0; i < s.dof; ++i) {
    upper[i] = enabled ? upper_[i]->value() : s.q_max[i] * kDegPerRad;
    lower[i] = enabled ? lower_[i]->value() : s.q_min[i] * kDegPerRad;
  }
  const xmate::model::ParameterProblem error = xmate::model::checkSoftLimits(s, upper, lower);
  if (!error.empty()) {
    if (error.index >= 0 && error.index < 7) {
      markInvalid(error.parameter == "upper" ? upper_[error.index] : lower_[error.index], true);
      if (error.text.find("must be below") != std::string::npos) markInvalid(upper_[error.index], true);
    }
    message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  message_->clearMessage();
  saveFields(lower_ + upper_);
  saveValue(QStringLiteral("enabled"), enabled);
  saveValue(QStringLiteral("auto_limit"), auto_limit);
  send(enabled ? tr("apply soft limits") : tr("remove soft limits"),
       [upper, lower, auto_limit](xmate::Robot& r) { r.setJointLimit(upper, lower, auto_limit); },
       [this, upper, lower, enabled] {
         OperatorSettings o = session().operatorSettings();
         o.soft_limits_enabled = enabled;
         o.soft_upper_deg = upper;
         o.soft_lower_deg = lower;
         session().setOperatorSettings(o);
       });
}

}  // namespace rci::ui
