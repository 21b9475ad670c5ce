// SPDX-License-Identifier: Apache-2.0
// Simulator panel: scene calls on the session's embedded sim::Server (server.h, "Scene").
#include "panels/simulator_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <exception>

#include "panels/fields.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui {

SimulatorPanel::SimulatorPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("simulator"), tr("Simulator"), parent) {
  auto* note = new QLabel(tr("Scene of the built-in simulator: the world around the simulated robot."), this);
  note->setObjectName(QStringLiteral("sim.note"));
  note->setWordWrap(true);
  body()->addWidget(note);
  body()->addWidget(makeWrenchGroup());
  body()->addWidget(makeStopsGroup());
  body()->addWidget(makeInputsGroup());
  message_ = new MessageLine(QStringLiteral("sim.message"), this);
  body()->addWidget(message_);
  loadFields(wrench_);
  updateAvailability();
}

QGroupBox* SimulatorPanel::makeWrenchGroup() {
  auto* group = new QGroupBox(tr("External wrench at the TCP (base frame)"), this);
  auto* grid = new QGridLayout(group);
  const char* names[6] = {"fx", "fy", "fz", "mx", "my", "mz"};
  const char* labels[6] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  for (int i = 0; i < 6; ++i) {
    const bool force = i < 3;
    auto* field = makeNumberField(QStringLiteral("sim.") + QLatin1String(names[i]), -500, 500, 1,
                                  force ? QStringLiteral("N") : QStringLiteral("Nm"),
                                  force ? tr("Force on the TCP along the base %1 axis").arg(QChar('x' + i))
                                        : tr("Moment about the base %1 axis at the TCP").arg(QChar('x' + i - 3)),
                                  group);
    grid->addWidget(new QLabel(QLatin1String(labels[i]), group), i % 3, 2 * (i / 3));
    grid->addWidget(field, i % 3, 2 * (i / 3) + 1);
    wrench_.append(field);
  }
  auto* apply = new QPushButton(tr("Apply"), group);
  apply->setObjectName(QStringLiteral("sim.wrench.apply"));
  apply->setToolTip(tr("Push the arm with this wrench until released; under position control a large one "
                       "trips the collision detection"));
  auto* release = new QPushButton(tr("Release"), group);
  release->setObjectName(QStringLiteral("sim.wrench.release"));
  release->setToolTip(tr("Take the external wrench away (zero)"));
  connect(apply, &QPushButton::clicked, this, [this] { applyWrench(false); });
  connect(release, &QPushButton::clicked, this, [this] { applyWrench(true); });
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(release);
  row->addWidget(apply);
  grid->addLayout(row, 3, 0, 1, 4);
  groups_.append(group);
  return group;
}

QGroupBox* SimulatorPanel::makeStopsGroup() {
  auto* group = new QGroupBox(tr("Stops"), this);
  auto* row = new QHBoxLayout(group);
  estop_ = new QPushButton(tr("E-stop"), group);
  estop_->setObjectName(QStringLiteral("sim.estop"));
  estop_->setCheckable(true);
  estop_->setToolTip(tr("Press / release the emergency stop: motors off, motion aborted"));
  gstop_ = new QPushButton(tr("Guard stop"), group);
  gstop_->setObjectName(QStringLiteral("sim.gstop"));
  gstop_->setCheckable(true);
  gstop_->setToolTip(tr("Open / close the guard (safety door): controlled stop, motors stay on"));
  connect(estop_, &QPushButton::clicked, this, [this](bool on) {
    scene(on ? tr("e-stop pressed") : tr("e-stop released"), [on](xmate::sim::Server& s) { s.setEmergencyStop(on); });
  });
  connect(gstop_, &QPushButton::clicked, this, [this](bool on) {
    scene(on ? tr("guard stop on") : tr("guard stop off"), [on](xmate::sim::Server& s) { s.setGuardStop(on); });
  });
  row->addWidget(estop_);
  row->addWidget(gstop_);
  row->addStretch(1);
  groups_.append(group);
  return group;
}

QGroupBox* SimulatorPanel::makeInputsGroup() {
  auto* group = new QGroupBox(tr("Digital inputs"), this);
  auto* grid = new QGridLayout(group);
  const char* names[6] = {"DI0_0", "DI0_1", "DI0_2", "DI0_3", "DI1_0", "DI1_1"};
  for (int i = 0; i < 6; ++i) {
    auto* box = new QCheckBox(QLatin1String(names[i]), group);
    box->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);  // the whole widget is clickable
    box->setObjectName(QStringLiteral("sim.di%1").arg(i));
    box->setToolTip(tr("Level of input %1 (ignored while the loop-back is on)").arg(QLatin1String(names[i])));
    connect(box, &QCheckBox::clicked, this, [this, i](bool on) {
      scene(tr("DI %1 %2").arg(i).arg(on ? tr("high") : tr("low")),
            [i, on](xmate::sim::Server& s) { s.setDigitalInput(i, on); });
    });
    grid->addWidget(box, i / 3, i % 3);
    inputs_[i] = box;
  }
  loopback_ = new QCheckBox(tr("Loop-back: DO k drives DI k"), group);
  loopback_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
  loopback_->setObjectName(QStringLiteral("sim.loopback"));
  loopback_->setToolTip(tr("Wire each digital output to the input of the same number"));
  connect(loopback_, &QCheckBox::clicked, this, [this](bool on) {
    scene(on ? tr("loop-back on") : tr("loop-back off"), [on](xmate::sim::Server& s) { s.setDoToDiLoopback(on); });
    for (auto* box : inputs_) box->setEnabled(!on);
  });
  grid->addWidget(loopback_, 2, 0, 1, 3);
  groups_.append(group);
  return group;
}

void SimulatorPanel::scene(const QString& what, const std::function<void(xmate::sim::Server&)>& call) {
  auto* sim = session().simulator();
  if (!sim) {
    message_->showError(tr("%1: no built-in simulator is running (connected to a real robot or not connected).")
                            .arg(what));
    return;
  }
  try {
    call(*sim);
    message_->showInfo(tr("%1.").arg(what.left(1).toUpper() + what.mid(1)));
    message_->setToolTip(QString());
    session().reportEvent(Session::EventLevel::kInfo, tr("%1: %2").arg(title(), what));
  } catch (const std::exception& e) {
    const text::OperatorMessage m = text::failure(e, text::viewOf(session()));
    message_->showError(tr("%1 failed: %2").arg(what, m.line()));
    message_->setToolTip(QString::fromUtf8(e.what()));
    session().reportEvent(Session::EventLevel::kError, tr("%1: %2 failed: %3").arg(title(), what, m.line()),
                          QString::fromUtf8(e.what()));
  }
}

void SimulatorPanel::applyWrench(bool release) {
  std::array<double, 6> w{};
  if (release) {
    for (auto* f : wrench_) f->setValue(0);
  } else {
    for (int i = 0; i < 6; ++i) w[i] = wrench_[i]->value();
    saveFields(wrench_);
  }
  scene(release ? tr("external wrench released") : tr("external wrench applied"),
        [w](xmate::sim::Server& s) { s.setExternalWrench(w); });
}

void SimulatorPanel::updateAvailability() {
  const bool available = session().simulator() != nullptr;
  for (auto* g : groups_) g->setEnabled(available);
  if (!available) message_->showInfo(tr("Available when connected to the built-in simulator."));
  else if (message_->kind() == QLatin1String("info")) message_->clearMessage();
}

void SimulatorPanel::sessionOpened() {
  updateAvailability();
  const bool loopback = session().target().loopback;
  loopback_->setChecked(loopback);
  for (auto* box : inputs_) box->setEnabled(!loopback);
}

void SimulatorPanel::sessionClosed() { updateAvailability(); }

void SimulatorPanel::refresh(const LiveState& live) {
  if (!live.simulated) return;
  // With both stops active the controller reports ESTOP: the guard button then keeps its state.
  estop_->setChecked(live.sim.safety_stop == 2);
  if (live.sim.safety_stop != 2) gstop_->setChecked(live.sim.safety_stop == 3);
  for (int i = 0; i < 6; ++i) inputs_[i]->setChecked(live.sim.digital_in[i]);
}

}  // namespace rci::ui
