// SPDX-License-Identifier: Apache-2.0
// Impedance panel: three validated editors, each with its own Apply and inline message.
#include "panels/impedance_panel.h"

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

namespace mc = xmate::model;

ImpedancePanel::ImpedancePanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("impedance"), tr("Impedance"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  const QStringList joints{"J1", "J2", "J3", "J4", "J5", "J6", "J7"};
  const QStringList cart{"x", "y", "z", "rx", "ry", "rz"};
  const QStringList wrench{"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  body()->addWidget(makeEditor(joint_, tr("Joint stiffness (joint impedance mode)"), QStringLiteral("impedance.joint"),
                               joints, 0, 20000, {QStringLiteral("Nm/rad")},
                               tr("Send the joint stiffness to the robot")));
  body()->addWidget(makeEditor(cartesian_, tr("Cartesian stiffness (Cartesian impedance mode)"),
                               QStringLiteral("impedance.cart"), cart, 0, 20000,
                               {QStringLiteral("N/m"), QStringLiteral("N/m"), QStringLiteral("N/m"),
                                QStringLiteral("Nm/rad"), QStringLiteral("Nm/rad"), QStringLiteral("Nm/rad")},
                               tr("Send the Cartesian stiffness to the robot")));
  body()->addWidget(makeEditor(wrench_, tr("Desired wrench (force-control frame)"),
                               QStringLiteral("impedance.wrench"), wrench, -1000, 1000,
                               {QStringLiteral("N"), QStringLiteral("N"), QStringLiteral("N"), QStringLiteral("Nm"),
                                QStringLiteral("Nm"), QStringLiteral("Nm")},
                               tr("Send the wrench the robot applies in Cartesian impedance mode")));
  for (int i = 0; i < 7; ++i) joint_.fields[i]->setValue(spec().joint_stiffness_max[i]);
  for (int i = 0; i < 6; ++i) cartesian_.fields[i]->setValue(mc::kCartesianStiffnessMax[i]);
  loadFields(joint_.fields + cartesian_.fields + wrench_.fields);
  showModel();
}

QGroupBox* ImpedancePanel::makeEditor(Editor& editor, const QString& title, const QString& prefix,
                                      const QStringList& labels, double min, double max, const QStringList& units,
                                      const QString& apply_tip) {
  auto* group = new QGroupBox(title, this);
  auto* grid = new QGridLayout(group);
  // Two columns, filled top to bottom: x y z | rx ry rz, J1-J4 | J5-J7.
  const int columns = 2;
  const int rows = int((labels.size() + columns - 1) / columns);
  for (int i = 0; i < labels.size(); ++i) {
    const QString unit = units.size() == 1 ? units[0] : units[i];
    auto* label = new QLabel(labels[i], group);
    auto* field = makeNumberField(prefix + QString::number(i + 1), min, max, 1, unit, QString(), group);
    grid->addWidget(label, i % rows, 2 * (i / rows));
    grid->addWidget(field, i % rows, 2 * (i / rows) + 1);
    editor.labels.append(label);
    editor.fields.append(field);
  }
  editor.message = new MessageLine(prefix + QStringLiteral(".message"), group);
  grid->addWidget(editor.message, rows, 0, 1, 2 * columns);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(prefix + QStringLiteral(".apply"));
  apply->setToolTip(apply_tip);
  addSendWidget(apply);
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, rows + 1, 0, 1, 2 * columns);
  if (&editor == &joint_) connect(apply, &QPushButton::clicked, this, &ImpedancePanel::applyJoint);
  if (&editor == &cartesian_) connect(apply, &QPushButton::clicked, this, &ImpedancePanel::applyCartesian);
  if (&editor == &wrench_) connect(apply, &QPushButton::clicked, this, &ImpedancePanel::applyWrench);
  return group;
}

void ImpedancePanel::showModel() {
  const auto& s = spec();
  for (int i = 0; i < 7; ++i) {
    joint_.fields[i]->setVisible(i < s.dof);
    joint_.labels[i]->setVisible(i < s.dof);
    if (i < s.dof && joint_.fields[i]->value() > s.joint_stiffness_max[i])
      joint_.fields[i]->setValue(s.joint_stiffness_max[i]);  // another model may allow less
    joint_.fields[i]->setToolTip(tr("Stiffness of joint %1: 0 to %2 Nm/rad").arg(i + 1).arg(s.joint_stiffness_max[i]));
  }
  for (int i = 0; i < 6; ++i) {
    cartesian_.fields[i]->setToolTip(tr("Cartesian stiffness along/about %1: 0 to %2 %3")
                                         .arg(cartesian_.labels[i]->text())
                                         .arg(mc::kCartesianStiffnessMax[i])
                                         .arg(i < 3 ? QStringLiteral("N/m") : QStringLiteral("Nm/rad")));
    const double max = i < 3 ? mc::kDesiredForceMaxN : mc::kDesiredTorqueMaxNm;
    wrench_.fields[i]->setToolTip(
        tr("Desired %1: -%2 to %2 %3").arg(wrench_.labels[i]->text()).arg(max).arg(i < 3 ? "N" : "Nm"));
  }
}

void ImpedancePanel::sessionOpened() { showModel(); }

bool ImpedancePanel::accept(Editor& editor, const xmate::model::ParameterProblem& error) {
  clearInvalid(editor.fields);
  if (error.empty()) {
    editor.message->clearMessage();
    saveFields(editor.fields);
    return true;
  }
  const int i = error.index;
  if (i >= 0 && i < editor.fields.size()) markInvalid(editor.fields[i], true);
  editor.message->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
  return false;
}

void ImpedancePanel::applyJoint() {
  std::array<double, 7> k{};
  for (int i = 0; i < dof(); ++i) k[i] = joint_.fields[i]->value();
  if (!accept(joint_, mc::checkJointImpedance(spec(), k))) return;
  send(tr("apply joint stiffness"), [k](xmate::Robot& r) { r.setJointImpedance(k); });
}

void ImpedancePanel::applyCartesian() {
  std::array<double, 6> k{};
  for (int i = 0; i < 6; ++i) k[i] = cartesian_.fields[i]->value();
  if (!accept(cartesian_, mc::checkCartesianImpedance(k))) return;
  send(tr("apply Cartesian stiffness"), [k](xmate::Robot& r) { r.setCartesianImpedance(k); });
}

void ImpedancePanel::applyWrench() {
  std::array<double, 6> w{};
  for (int i = 0; i < 6; ++i) w[i] = wrench_.fields[i]->value();
  if (!accept(wrench_, mc::checkDesiredWrench(w))) return;
  send(tr("apply desired wrench"), [w](xmate::Robot& r) { r.setCartImpDesiredTau(w); });
}

}  // namespace rci::ui
