// SPDX-License-Identifier: Apache-2.0
// Filters panel: cut-offs checked with parameter_checks (refusal) and the 10-100 Hz advice (warning).
#include "panels/filters_panel.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPushButton>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

namespace mc = xmate::model;

FiltersPanel::FiltersPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("filters"), tr("Filters"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  auto* group = new QGroupBox(tr("Command low-pass filters"), this);
  auto* form = new QFormLayout(group);
  const QString range = tr("allowed %1-%2 Hz, recommended %3-%4 Hz")
                            .arg(mc::kFilterMinHz)
                            .arg(mc::kFilterMaxHz)
                            .arg(mc::kFilterRecommendedMinHz)
                            .arg(mc::kFilterRecommendedMaxHz);
  const struct {
    const char* name;
    QString label, tip;
  } rows[3] = {
      {"filters.joint", tr("Joint position"), tr("Cut-off of the joint position command filter (%1)").arg(range)},
      {"filters.cartesian", tr("Cartesian position"),
       tr("Cut-off of the Cartesian position command filter (%1)").arg(range)},
      {"filters.torque", tr("Torque"), tr("Cut-off of the torque command filter (%1)").arg(range)},
  };
  for (const auto& row : rows) {
    auto* field = makeNumberField(QLatin1String(row.name), 0, 5000, 1, QStringLiteral("Hz"), row.tip, group);
    field->setValue(100);
    form->addRow(row.label, field);
    fields_.append(field);
  }
  message_ = new MessageLine(QStringLiteral("filters.message"), group);
  form->addRow(message_);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("filters.apply"));
  apply->setToolTip(tr("Send the cut-off frequencies to the robot"));
  addSendWidget(apply);
  auto* buttons = new QHBoxLayout;
  buttons->addStretch(1);
  buttons->addWidget(apply);
  form->addRow(buttons);
  body()->addWidget(group);

  loadFields(fields_);
  connect(apply, &QPushButton::clicked, this, &FiltersPanel::apply);
}

QString FiltersPanel::recommendationWarning() const {
  const char* names[3] = {"joint", "Cartesian", "torque"};
  QStringList outside;
  for (int i = 0; i < 3; ++i) {
    const double v = fields_[i]->value();
    if (v < mc::kFilterRecommendedMinHz || v > mc::kFilterRecommendedMaxHz)
      outside << tr("%1 %2 Hz").arg(QLatin1String(names[i])).arg(v);
  }
  if (outside.isEmpty()) return {};
  return tr("Accepted, but %1 is outside the recommended %2-%3 Hz: a low cut-off delays the commands, a high "
            "one lets jerky commands through.")
      .arg(outside.join(QStringLiteral(", ")))
      .arg(mc::kFilterRecommendedMinHz)
      .arg(mc::kFilterRecommendedMaxHz);
}

void FiltersPanel::apply() {
  clearInvalid(fields_);
  const double joint = fields_[0]->value(), cart = fields_[1]->value(), torque = fields_[2]->value();
  const mc::ParameterProblem error = mc::checkFilters(joint, cart, torque);
  if (!error.empty()) {
    const char* params[3] = {"joint_hz", "cartesian_hz", "torque_hz"};
    for (int i = 0; i < 3; ++i)
      if (error.parameter == params[i]) markInvalid(fields_[i], true);
    message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  const QString warning = recommendationWarning();
  if (warning.isEmpty())
    message_->clearMessage();
  else
    message_->showWarning(warning);
  saveFields(fields_);
  send(tr("apply filters"), [joint, cart, torque](xmate::Robot& r) { r.setFilters(joint, cart, torque); });
}

}  // namespace rci::ui
