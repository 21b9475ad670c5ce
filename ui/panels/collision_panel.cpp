// SPDX-License-Identifier: Apache-2.0
// Collision panel: validated thresholds sent with setCollisionBehavior; |tau_ext| bars per joint.
#include "panels/collision_panel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <algorithm>
#include <cmath>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

CollisionPanel::CollisionPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("collision"), tr("Collision"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  auto* group = new QGroupBox(tr("Collision detection thresholds"), this);
  auto* grid = new QGridLayout(group);
  grid->addWidget(new QLabel(tr("Joint"), group), 0, 0);
  grid->addWidget(new QLabel(tr("Threshold"), group), 0, 1);
  grid->addWidget(new QLabel(tr("|External torque| / threshold"), group), 0, 2);
  for (int i = 0; i < 7; ++i) {
    names_[i] = new QLabel(QStringLiteral("J%1").arg(i + 1), group);
    auto* field = makeNumberField(QStringLiteral("collision.threshold%1").arg(i + 1), 0, 1000, 1,
                                  QStringLiteral("Nm"), QString(), group);
    fields_.append(field);
    auto* bar = new QProgressBar(group);
    bar->setObjectName(QStringLiteral("collision.bar%1").arg(i + 1));
    bar->setTextVisible(true);
    bar->setToolTip(tr("Estimated external torque of joint %1 against its threshold; the robot stops when it "
                       "exceeds the threshold under position control")
                        .arg(i + 1));
    bars_[i] = bar;
    grid->addWidget(names_[i], i + 1, 0);
    grid->addWidget(field, i + 1, 1);
    grid->addWidget(bar, i + 1, 2);
  }
  grid->setColumnStretch(2, 1);
  message_ = new MessageLine(QStringLiteral("collision.message"), group);
  grid->addWidget(message_, 8, 0, 1, 3);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("collision.apply"));
  apply->setToolTip(tr("Send the thresholds to the robot; they act while the robot holds or follows a position"));
  addSendWidget(apply);
  connect(apply, &QPushButton::clicked, this, &CollisionPanel::apply);
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, 9, 0, 1, 3);
  body()->addWidget(group);

  for (int i = 0; i < 7; ++i) fields_[i]->setValue(spec().collision_threshold_max[i]);
  loadFields(fields_);
  showModel();
}

void CollisionPanel::showModel() {
  const auto& s = spec();
  for (int i = 0; i < 7; ++i) {
    const bool used = i < s.dof;
    names_[i]->setVisible(used);
    fields_[i]->setVisible(used);
    bars_[i]->setVisible(used);
    // Another model may allow less: start from its maximum rather than from a refused value.
    if (used && fields_[i]->value() > s.collision_threshold_max[i]) fields_[i]->setValue(s.collision_threshold_max[i]);
    fields_[i]->setToolTip(tr("Collision threshold of joint %1: more than 0 and at most %2 Nm on the %3")
                               .arg(i + 1)
                               .arg(s.collision_threshold_max[i])
                               .arg(QLatin1String(s.display_name.data(), qsizetype(s.display_name.size()))));
  }
}

void CollisionPanel::sessionOpened() { showModel(); }

std::array<double, 7> CollisionPanel::thresholds() const {
  std::array<double, 7> t{};
  for (int i = 0; i < dof(); ++i) t[i] = fields_[i]->value();
  return t;
}

void CollisionPanel::apply() {
  clearInvalid(fields_);
  const auto t = thresholds();
  const xmate::model::ParameterProblem error = xmate::model::checkCollisionThresholds(spec(), t);
  if (!error.empty()) {
    const int i = error.index;
    if (i >= 0 && i < fields_.size()) markInvalid(fields_[i], true);
    message_->showError(tr("Not sent: %1. Enter a value within the range shown in the field's tooltip.")
                            .arg(text::valueRefusal(error)));
    return;
  }
  message_->clearMessage();
  saveFields(fields_);
  send(tr("apply thresholds"), [t](xmate::Robot& r) { r.setCollisionBehavior(t); },
       [this, t] {
         OperatorSettings s = session().operatorSettings();
         s.collision_thresholds = t;
         session().setOperatorSettings(s);
       });
}

double CollisionPanel::barThreshold(int joint) const {
  const double set = session().operatorSettings().collision_thresholds[joint];
  return set > 0 ? set : spec().collision_threshold_max[joint];
}

void CollisionPanel::refresh(const LiveState& live) {
  for (int i = 0; i < live.dof && i < 7; ++i) {
    const double threshold = barThreshold(i);
    const double value = std::abs(live.tau_ext[i]);
    bars_[i]->setRange(0, int(std::lround(threshold * 10)));
    bars_[i]->setValue(int(std::lround(std::min(value, threshold) * 10)));
    bars_[i]->setFormat(QStringLiteral("%1 / %2 Nm").arg(value, 0, 'f', 1).arg(threshold, 0, 'f', 1));
    const double ratio = threshold > 0 ? value / threshold : 0;
    const char* color = ratio >= 1.0 ? "#d22d2d" : ratio >= 0.7 ? "#eba014" : "#2eaa46";
    if (bar_colors_[i] == color) continue;  // restyling is costly: only when the colour changes
    bar_colors_[i] = color;
    bars_[i]->setStyleSheet(QStringLiteral("QProgressBar::chunk { background: %1; }").arg(QLatin1String(color)));
  }
}

}  // namespace rci::ui
