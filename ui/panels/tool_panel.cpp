// SPDX-License-Identifier: Apache-2.0
// Tool & payload panel: validated TCP frame (setCoor) and payload (setLoad) editors.
#include "panels/tool_panel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <Eigen/Geometry>

#include "model/parameter_checks.h"
#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

namespace mc = xmate::model;

std::array<double, 16> toolFrameFromXyzRpy(const std::array<double, 6>& v) {
  const double k = 1.0 / kDegPerRad;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(v[5] * k, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(v[4] * k, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(v[3] * k, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  std::array<double, 16> m{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r(i, j);
    m[4 * i + 3] = v[i];
  }
  m[15] = 1;
  return m;
}

ToolPanel::ToolPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("tool"), tr("Tool & payload"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kControllerSafety));
  body()->addWidget(makeToolGroup());
  body()->addWidget(makePayloadGroup());
  loadFields(tool_ + centre_ + inertia_ + QList<QDoubleSpinBox*>{mass_});
}

QGroupBox* ToolPanel::makeToolGroup() {
  auto* group = new QGroupBox(tr("Tool centre point (relative to the flange)"), this);
  auto* grid = new QGridLayout(group);
  const char* names[6] = {"x", "y", "z", "rx", "ry", "rz"};
  for (int i = 0; i < 6; ++i) {
    const bool linear = i < 3;
    const QString name = QLatin1String(names[i]);
    auto* field = linear ? makeNumberField(QStringLiteral("tool.") + name, -2, 2, 4, QStringLiteral("m"),
                                           tr("TCP offset along the flange's %1 axis; the TCP may be at most %2 m "
                                              "from the flange")
                                               .arg(name)
                                               .arg(mc::kToolOffsetMaxM),
                                           group)
                         : makeNumberField(QStringLiteral("tool.") + name, -360, 360, 2, QStringLiteral("deg"),
                                           tr("TCP rotation about the flange's %1 axis; applied as "
                                              "Rz(rz) Ry(ry) Rx(rx)")
                                               .arg(name.mid(1)),
                                           group);
    if (linear) field->setSingleStep(0.005);
    grid->addWidget(new QLabel(name, group), i % 3, 2 * (i / 3));
    grid->addWidget(field, i % 3, 2 * (i / 3) + 1);
    tool_.append(field);
  }
  tool_message_ = new MessageLine(QStringLiteral("tool.message"), group);
  grid->addWidget(tool_message_, 3, 0, 1, 4);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("tool.apply"));
  apply->setToolTip(tr("Send the TCP frame to the robot; it forgets it when the controller restarts"));
  addSendWidget(apply);
  connect(apply, &QPushButton::clicked, this, &ToolPanel::applyTool);
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, 4, 0, 1, 4);
  return group;
}

QGroupBox* ToolPanel::makePayloadGroup() {
  auto* group = new QGroupBox(tr("Payload"), this);
  auto* grid = new QGridLayout(group);
  mass_ = makeNumberField(QStringLiteral("payload.mass"), 0, 100, 3, QStringLiteral("kg"),
                          tr("Payload mass: 0 up to the rated payload of the model"), group);
  grid->addWidget(new QLabel(tr("Mass"), group), 0, 0);
  grid->addWidget(mass_, 0, 1);
  const char* centre[3] = {"cx", "cy", "cz"};
  for (int i = 0; i < 3; ++i) {
    auto* field = makeNumberField(QStringLiteral("payload.") + QLatin1String(centre[i]), -2, 2, 4, QStringLiteral("m"),
                                  tr("Centre of mass in the flange frame, within +-%1 m").arg(mc::kLoadCenterMaxM),
                                  group);
    field->setSingleStep(0.005);
    grid->addWidget(new QLabel(QLatin1String(centre[i]), group), i + 1, 0);
    grid->addWidget(field, i + 1, 1);
    centre_.append(field);
  }
  const char* inertia[6] = {"ixx", "iyy", "izz", "ixy", "ixz", "iyz"};
  for (int i = 0; i < 6; ++i) {
    auto* field = makeNumberField(QStringLiteral("payload.") + QLatin1String(inertia[i]), -10, 10, 5,
                                  QStringLiteral("kg m²"),
                                  tr("Inertia about the centre of mass (flange axes); the tensor must be symmetric "
                                     "positive semi-definite and satisfy the triangle inequality"),
                                  group);
    field->setSingleStep(0.0001);
    field->setMinimumWidth(125);
    const QString label = QLatin1Char('I') + QLatin1String(inertia[i] + 1);
    // Two columns, so the group fits a narrow dock: mass and centre on the left, the inertia on the right.
    grid->addWidget(new QLabel(label, group), i, 2);
    grid->addWidget(field, i, 3);
    inertia_.append(field);
  }
  payload_message_ = new MessageLine(QStringLiteral("payload.message"), group);
  grid->addWidget(payload_message_, 6, 0, 1, 4);
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("payload.apply"));
  apply->setToolTip(tr("Send the payload to the robot; a wrong payload shows up as external torque"));
  addSendWidget(apply);
  connect(apply, &QPushButton::clicked, this, &ToolPanel::applyPayload);
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(apply);
  grid->addLayout(row, 7, 0, 1, 4);
  return group;
}

void ToolPanel::applyTool() {
  clearInvalid(tool_);
  std::array<double, 6> v{};
  for (int i = 0; i < 6; ++i) v[i] = tool_[i]->value();
  const auto frame = toolFrameFromXyzRpy(v);
  const mc::ParameterProblem error = mc::checkToolFrame(frame);
  if (!error.empty()) {
    for (int i = 0; i < 3; ++i) markInvalid(tool_[i], true);
    tool_message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  tool_message_->clearMessage();
  saveFields(tool_);
  send(tr("apply TCP"), [frame](xmate::Robot& r) { r.setCoor(frame); });
}

void ToolPanel::applyPayload() {
  clearInvalid(centre_ + inertia_ + QList<QDoubleSpinBox*>{mass_});
  const double mass = mass_->value();
  const std::array<double, 3> centre{centre_[0]->value(), centre_[1]->value(), centre_[2]->value()};
  const double ixx = inertia_[0]->value(), iyy = inertia_[1]->value(), izz = inertia_[2]->value();
  const double ixy = inertia_[3]->value(), ixz = inertia_[4]->value(), iyz = inertia_[5]->value();
  const std::array<double, 9> inertia{ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz};
  const mc::ParameterProblem error = mc::checkLoad(spec(), mass, centre, inertia);
  if (!error.empty()) {
    if (error.parameter == "mass") markInvalid(mass_, true);
    if (error.parameter == "center" && error.index >= 0 && error.index < 3) markInvalid(centre_[error.index], true);
    if (error.parameter == "inertia")
      for (auto* f : inertia_) markInvalid(f, true);
    payload_message_->showError(tr("Not sent: %1.").arg(text::valueRefusal(error)));
    return;
  }
  payload_message_->clearMessage();
  saveFields(centre_ + inertia_ + QList<QDoubleSpinBox*>{mass_});
  send(tr("apply payload"), [mass, centre, inertia](xmate::Robot& r) { r.setLoad(mass, centre, inertia); });
}

}  // namespace rci::ui
