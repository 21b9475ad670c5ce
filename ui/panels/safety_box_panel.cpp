// SPDX-License-Identifier: Apache-2.0
// Safety box panel: validated box (parameter_checks) sent by setCartesianLimit, then recorded.
#include "panels/safety_box_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

SafetyBoxPanel::SafetyBoxPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("box"), tr("Safety box"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  auto* group = new QGroupBox(tr("Cartesian safety box (base frame)"), this);
  group->setToolTip(tr("While the motors are on and the box is enabled, the TCP leaving the box switches the "
                       "motors off. It is a safety limit, not a force-control wall."));
  auto* grid = new QGridLayout(group);
  const char* axes[3] = {"x", "y", "z"};
  grid->addWidget(new QLabel(tr("Size"), group), 0, 1);
  grid->addWidget(new QLabel(tr("Centre"), group), 0, 2);
  const OperatorSettings defaults;
  for (int i = 0; i < 3; ++i) {
    const QString axis = QLatin1String(axes[i]);
    grid->addWidget(new QLabel(axis, group), i + 1, 0);
    auto* size = makeNumberField(QStringLiteral("box.size") + axis, 0, 20, 3, QStringLiteral("m"),
                                 tr("Full edge length along %1: more than 0, at most %2 m")
                                     .arg(axis)
                                     .arg(xmate::model::kSafetyBoxMaxSizeM),
                                 group);
    size->setSingleStep(0.05);
    size->setValue(defaults.box.size[i]);
    auto* centre = makeNumberField(QStringLiteral("box.") + axis, -10, 10, 3, QStringLiteral("m"),
                                   tr("Centre of the box, %1 in the robot base frame").arg(axis), group);
    centre->setSingleStep(0.05);
    centre->setValue(defaults.box.frame[4 * i + 3]);
    grid->addWidget(size, i + 1, 1);
    grid->addWidget(centre, i + 1, 2);
    size_.append(size);
    centre_.append(centre);
  }
  enabled_ = new QCheckBox(tr("Enabled"), group);
  enabled_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  enabled_->setObjectName(QStringLiteral("box.enable"));
  enabled_->setToolTip(tr("Activate the box: leaving it switches the motors off"));
  grid->addWidget(enabled_, 4, 1);
  message_ = new MessageLine(QStringLiteral("box.message"), group);
  grid->addWidget(message_, 5, 0, 1, 3);

  auto* row = new QHBoxLayout;
  auto* from_tcp = new QPushButton(tr("Centre on TCP"), group);
  from_tcp->setObjectName(QStringLiteral("box.fromtcp"));
  from_tcp->setToolTip(tr("Put the centre at the current measured TCP position"));
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("box.apply"));
  apply->setToolTip(tr("Send the box to the robot"));
  addSendWidget(from_tcp);
  addSendWidget(apply);
  row->addWidget(from_tcp);
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, 6, 0, 1, 3);
  body()->addWidget(group);

  loadFields(size_ + centre_);
  enabled_->setChecked(loadValue(QStringLiteral("enabled"), false).toBool());
  connect(apply, &QPushButton::clicked, this, &SafetyBoxPanel::apply);
  connect(from_tcp, &QPushButton::clicked, this, &SafetyBoxPanel::centreOnTcp);
}

void SafetyBoxPanel::centreOnTcp() {
  const LiveState& live = session().live();
  if (!live.has_state) {
    message_->showError(tr("No robot state yet: wait until the robot streams its state."));
    return;
  }
  for (int i = 0; i < 3; ++i) centre_[i]->setValue(live.state.toolTobase_pos_m[4 * i + 3]);
  message_->clearMessage();
}

void SafetyBoxPanel::apply() {
  clearInvalid(size_);
  SafetyBox box;
  box.enabled = enabled_->isChecked();
  box.frame = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  for (int i = 0; i < 3; ++i) {
    box.size[i] = size_[i]->value();
    box.frame[4 * i + 3] = centre_[i]->value();
  }
  const xmate::model::ParameterProblem error = xmate::model::checkCartesianLimit(box.size, box.frame);
  if (!error.empty()) {
    const int i = error.parameter == "size" ? error.index : -1;
    if (i >= 0 && i < 3) markInvalid(size_[i], true);
    message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  message_->clearMessage();
  saveFields(size_ + centre_);
  saveValue(QStringLiteral("enabled"), box.enabled);
  send(box.enabled ? tr("enable box") : tr("disable box"),
       [box](xmate::Robot& r) { r.setCartesianLimit(box.size, box.frame, box.enabled); },
       [this, box] {
         OperatorSettings s = session().operatorSettings();
         s.box = box;
         session().setOperatorSettings(s);
       });
}

}  // namespace rci::ui
