// SPDX-License-Identifier: Apache-2.0
// Simulator panel: scene calls on the session's embedded sim::Server (server.h, "Scene") or on the
// built-in KUKA simulator's sim::Krc (krc.h, "Scene and faults").
#include "panels/simulator_panel.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayoutItem>
#include <QPushButton>
#include <QVBoxLayout>

#include <cmath>
#include <exception>

#include "model/signal_names.h"
#include "panels/fields.h"
#include "session/session.h"
#include "sim/krc.h"
#include "sim/krc_server.h"
#include "text/operator_text.h"

namespace rci::ui {
namespace {

// The simulated KRC's state in operator words.
QString krcStateText(const xmate::sim::KrcStatus& k, int cycle_ms, double restart_s) {
  using xmate::sim::KrcState;
  switch (k.state) {
    case KrcState::kRunning:
      return SimulatorPanel::tr("RSI is on (session %1): the controller sends every %2 ms and follows this PC's "
                                "corrections.")
          .arg(k.session)
          .arg(cycle_ms);
    case KrcState::kPaused:
      return SimulatorPanel::tr("RSI stopped on an error; the controller switches it on again %1 s after the stop.")
          .arg(restart_s, 0, 'g', 3);
    case KrcState::kStopped:
      return SimulatorPanel::tr("RSI stopped on an error and stays off: connect again to restart the simulator.");
    case KrcState::kSuspended:
      return SimulatorPanel::tr("RSI is off on purpose; it comes on again when the time set has passed.");
  }
  return QString();
}

QString krcStopText(xmate::sim::KrcStop stop) {
  using xmate::sim::KrcStop;
  switch (stop) {
    case KrcStop::kNone: return SimulatorPanel::tr("RSI has not stopped since the simulator started.");
    case KrcStop::kTimeout:
      return SimulatorPanel::tr("Last stop: too many answers from this PC missing or late in a row (RSITimeout).");
    case KrcStop::kAxisMonitor:
      return SimulatorPanel::tr("Last stop: an axis correction went beyond the limit the RSI context monitors.");
    case KrcStop::kPosMonitor:
      return SimulatorPanel::tr("Last stop: a Cartesian correction went beyond the limit the RSI context monitors.");
    case KrcStop::kUnreachable: return SimulatorPanel::tr("Last stop: the corrected pose could not be reached.");
    case KrcStop::kSuspended: return SimulatorPanel::tr("Last stop: RSI switched off on purpose for a while.");
  }
  return QString();
}

QPushButton* makeButton(const QString& name, const QString& text, const QString& tip, QWidget* parent) {
  auto* button = new QPushButton(text, parent);
  button->setObjectName(name);
  button->setToolTip(tip);
  compactButton(button);
  return button;
}

// The pause before the built-in KUKA simulator switches RSI on again after an error (the session
// starts it with the default configuration).
double restartPauseSeconds() { return xmate::sim::KrcConfig{}.restart_pause_ms / 1000.0; }

}  // namespace

SimulatorPanel::SimulatorPanel(Session& session, QWidget* parent)
    : PanelBase(session, QStringLiteral("simulator"), tr("Simulator"), parent) {
  note_ = new QLabel(tr("Scene of the built-in simulator: the world around the simulated robot."), this);
  note_->setObjectName(QStringLiteral("sim.note"));
  note_->setWordWrap(true);
  body()->addWidget(note_);
  body()->addWidget(makeWrenchGroup());
  body()->addWidget(makeStopsGroup());
  body()->addWidget(makeInputsGroup());
  body()->addWidget(makeKukaInputsGroup());
  body()->addWidget(makeOverrideGroup());
  body()->addWidget(makeFaultsGroup());
  message_ = new MessageLine(QStringLiteral("sim.message"), this);
  body()->addWidget(message_);
  loadFields(wrench_);
  updateAvailability();
}

bool SimulatorPanel::appliesTo(Session& session) const {
  return session.simulator() != nullptr || session.kukaSimulator() != nullptr;
}

QGroupBox* SimulatorPanel::makeWrenchGroup() {
  auto* group = new QGroupBox(tr("External wrench at the TCP (base frame)"), this);
  wrench_group_ = group;
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
  xmate_groups_.append(group);
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
  xmate_groups_.append(group);
  return group;
}

QGroupBox* SimulatorPanel::makeKukaInputsGroup() {
  auto* group = new QGroupBox(tr("Digital inputs of the controller"), this);
  group->setObjectName(QStringLiteral("sim.kuka.inputs"));
  auto* layout = new QVBoxLayout(group);
  layout->setContentsMargins(0, 0, 0, 0);
  kuka_inputs_area_ = new QWidget(group);
  layout->addWidget(kuka_inputs_area_);
  kuka_inputs_grid_ = new QGridLayout(kuka_inputs_area_);
  kuka_groups_.append(group);
  return group;
}

void SimulatorPanel::rebuildKukaInputs() {
  while (QLayoutItem* item = kuka_inputs_grid_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  kuka_inputs_.clear();
  kuka_input_signals_.clear();
  xmate::arm::Arm* arm = session().arm();
  if (!arm || !session().kukaSimulator()) return;
  const auto names = arm->inputNames();
  for (size_t k = 0; k < names.size(); ++k) {
    const QString name = QString::fromStdString(names[k]);
    const int signal = xmate::model::diIndex(spec().family, names[k]);
    auto* box = new QCheckBox(name, kuka_inputs_area_);
    box->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
    box->setObjectName(QStringLiteral("sim.in%1").arg(k));
    box->setToolTip(tr("Level of the controller's input %1 (the RSI context passes it to this PC)").arg(name));
    connect(box, &QCheckBox::clicked, this, [this, name, signal](bool on) {
      kukaScene(tr("%1 %2").arg(name, on ? tr("high") : tr("low")),
                [signal, on](xmate::sim::Krc& krc) { krc.setDigitalInput(signal, on); });
    });
    kuka_inputs_grid_->addWidget(box, int(k) / 4, int(k) % 4);
    kuka_inputs_.push_back(box);
    kuka_input_signals_.push_back(signal);
  }
  if (names.empty())
    kuka_inputs_grid_->addWidget(new QLabel(tr("The RSI context passes no inputs to this PC."), kuka_inputs_area_), 0, 0);
}

QGroupBox* SimulatorPanel::makeOverrideGroup() {
  auto* group = new QGroupBox(tr("Override"), this);
  auto* row = new QHBoxLayout(group);
  override_ = makeNumberField(QStringLiteral("sim.override"), 0, 100, 0, QStringLiteral("%"),
                              tr("The program override the smartPAD would set (the RSI context reads it)"), group);
  override_->setValue(100);
  auto* apply = makeButton(QStringLiteral("sim.override.apply"), tr("Set"),
                           tr("Set the simulated controller's program override"), group);
  connect(apply, &QPushButton::clicked, this, [this] {
    const double percent = override_->value();
    kukaScene(tr("override %1 %").arg(percent, 0, 'f', 0),
              [percent](xmate::sim::Krc& krc) { krc.setOverride(percent); });
  });
  row->addWidget(override_);
  row->addWidget(apply);
  row->addStretch(1);
  kuka_groups_.append(group);
  return group;
}

QGroupBox* SimulatorPanel::makeFaultsGroup() {
  auto* group = new QGroupBox(tr("RSI faults"), this);
  auto* grid = new QGridLayout(group);
  drop_cycles_ = makeNumberField(QStringLiteral("sim.fault.drop.cycles"), 1, 100000, 0, tr("cycles"),
                                 tr("How many of this PC's answers the controller does not receive"), group);
  drop_cycles_->setValue(101);
  auto* drop = makeButton(QStringLiteral("sim.fault.drop"), tr("Stop answering"),
                          tr("The controller receives none of this PC's answers for that many cycles"), group);
  connect(drop, &QPushButton::clicked, this, [this] {
    const int count = int(drop_cycles_->value());
    kukaScene(tr("answers lost for %1 cycles").arg(count), [count](xmate::sim::Krc& krc) { krc.dropAnswers(count); });
  });
  delay_cycles_ = makeNumberField(QStringLiteral("sim.fault.delay.cycles"), 1, 100000, 0, tr("cycles"),
                                  tr("How many of this PC's answers arrive after their cycle"), group);
  delay_cycles_->setValue(20);
  auto* delay = makeButton(QStringLiteral("sim.fault.delay"), tr("Late answers"),
                           tr("The next answers of this PC reach the controller after their cycle"), group);
  connect(delay, &QPushButton::clicked, this, [this] {
    const int count = int(delay_cycles_->value());
    kukaScene(tr("%1 answers late").arg(count), [count](xmate::sim::Krc& krc) { krc.delayAnswers(count); });
  });
  suspend_seconds_ = makeNumberField(QStringLiteral("sim.fault.suspend.seconds"), 0.1, 600, 1, QStringLiteral("s"),
                                     tr("How long the controller keeps RSI off"), group);
  suspend_seconds_->setValue(3);
  auto* suspend = makeButton(QStringLiteral("sim.fault.suspend"), tr("RSI off"),
                             tr("The controller switches RSI off for that long, without an error, then on again"),
                             group);
  connect(suspend, &QPushButton::clicked, this, [this] {
    const double seconds = suspend_seconds_->value();
    const int ms = int(std::lround(seconds * 1000));
    kukaScene(tr("RSI off for %1 s").arg(seconds, 0, 'g', 3), [ms](xmate::sim::Krc& krc) { krc.suspendSending(ms); });
  });
  grid->addWidget(drop, 0, 0);
  grid->addWidget(drop_cycles_, 0, 1);
  grid->addWidget(delay, 1, 0);
  grid->addWidget(delay_cycles_, 1, 1);
  grid->addWidget(suspend, 2, 0);
  grid->addWidget(suspend_seconds_, 2, 1);
  grid->setColumnStretch(2, 1);
  faults_help_ = new QLabel(group);
  faults_help_->setObjectName(QStringLiteral("sim.fault.help"));
  faults_help_->setWordWrap(true);
  grid->addWidget(faults_help_, 3, 0, 1, 3);
  krc_state_ = new QLabel(group);
  krc_state_->setObjectName(QStringLiteral("sim.krc.state"));
  krc_state_->setWordWrap(true);
  grid->addWidget(krc_state_, 4, 0, 1, 3);
  kuka_groups_.append(group);
  return group;
}

void SimulatorPanel::runScene(const QString& what, bool available, const std::function<void()>& call) {
  if (!available) {
    message_->showError(tr("%1: no built-in simulator is running (connected to a real robot or not connected).")
                            .arg(what));
    return;
  }
  try {
    call();
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

void SimulatorPanel::scene(const QString& what, const std::function<void(xmate::sim::Server&)>& call) {
  xmate::sim::Server* sim = session().simulator();
  runScene(what, sim != nullptr, [&] { call(*sim); });
}

void SimulatorPanel::kukaScene(const QString& what, const std::function<void(xmate::sim::Krc&)>& call) {
  xmate::sim::KrcServer* sim = session().kukaSimulator();
  runScene(what, sim != nullptr, [&] { call(sim->krc()); });
}

void SimulatorPanel::applyWrench(bool release) {
  std::array<double, 6> w{};
  if (release) {
    for (auto* f : wrench_) f->setValue(0);
  } else {
    for (int i = 0; i < 6; ++i) w[i] = wrench_[i]->value();
    saveFields(wrench_);
  }
  const QString what = release ? tr("external wrench released") : tr("external wrench applied");
  if (session().kukaSimulator())
    kukaScene(what, [w](xmate::sim::Krc& krc) { krc.setExternalWrench(w); });
  else
    scene(what, [w](xmate::sim::Server& s) { s.setExternalWrench(w); });
}

void SimulatorPanel::updateAvailability() {
  const bool xmate = session().simulator() != nullptr;
  const bool kuka = session().kukaSimulator() != nullptr;
  if (xmate || kuka) showing_kuka_ = kuka;  // closed: the last simulator's controls stay (disabled)
  for (auto* g : xmate_groups_) {
    g->setVisible(!showing_kuka_);
    g->setEnabled(xmate);
  }
  for (auto* g : kuka_groups_) {
    g->setVisible(showing_kuka_);
    g->setEnabled(kuka);
  }
  wrench_group_->setEnabled(xmate || kuka);
  wrench_group_->setTitle(showing_kuka_ ? tr("Push at the flange (base frame)")
                                        : tr("External wrench at the TCP (base frame)"));
  const QString at = showing_kuka_ ? tr("the flange") : tr("the TCP");
  for (int i = 0; i < 6; ++i)
    wrench_[i]->setToolTip(i < 3 ? tr("Force on %1 along the base %2 axis").arg(at).arg(QChar('x' + i))
                                 : tr("Moment about the base %1 axis at %2").arg(QChar('x' + i - 3)).arg(at));
  note_->setText(showing_kuka_ ? tr("Scene of the built-in KUKA simulator: the world around the simulated robot "
                                    "and faults of the RSI connection, to see how the window recovers.")
                               : tr("Scene of the built-in simulator: the world around the simulated robot."));
  if (!xmate && !kuka) message_->showInfo(tr("Available when connected to a built-in simulator."));
  else if (message_->kind() == QLatin1String("info")) message_->clearMessage();
}

void SimulatorPanel::sessionOpened() {
  rebuildKukaInputs();
  updateAvailability();
  const bool loopback = session().target().loopback;
  loopback_->setChecked(loopback);
  for (auto* box : inputs_) box->setEnabled(!loopback);
  if (xmate::sim::KrcServer* sim = session().kukaSimulator()) {
    const xmate::sim::Krc& krc = sim->krc();
    const int timeout = krc.timeoutLimit(), cycle = krc.cycleMs();
    drop_cycles_->setValue(timeout + 1);
    faults_help_->setText(
        tr("Stop answering: the controller gets no answer from this PC for that many cycles. After %1 missing "
           "answers in a row (%2 ms) it stops RSI with RSITimeout; the window then shows RSI stopped, a motion "
           "that was running ends. The controller switches RSI on again %3 s later and the window carries on with "
           "it by itself -- start the motion again.\n"
           "Late answers: the controller counts them (Delay) and keeps RSI on while fewer than %1 come in a row.\n"
           "RSI off: the controller switches RSI off without an error and on again after the time given.")
            .arg(timeout + 1)
            .arg((timeout + 1) * cycle)
            .arg(restartPauseSeconds(), 0, 'g', 3));
  }
}

void SimulatorPanel::sessionClosed() { updateAvailability(); }

void SimulatorPanel::refresh(const LiveState& live) {
  if (live.simulated) {
    // With both stops active the controller reports ESTOP: the guard button then keeps its state.
    estop_->setChecked(live.sim.safety_stop == 2);
    if (live.sim.safety_stop != 2) gstop_->setChecked(live.sim.safety_stop == 3);
    for (int i = 0; i < 6; ++i) inputs_[i]->setChecked(live.sim.digital_in[i]);
  }
  if (live.kuka_simulated) {
    for (size_t k = 0; k < kuka_inputs_.size(); ++k) {
      const int signal = kuka_input_signals_[k];
      kuka_inputs_[k]->setChecked(signal >= 1 && signal <= 64 && ((live.krc.digin >> (signal - 1)) & 1u) != 0);
    }
    const xmate::sim::KrcServer* sim = session().kukaSimulator();
    const int cycle = sim ? sim->krc().cycleMs() : 4;
    krc_state_->setText(krcStateText(live.krc, cycle, restartPauseSeconds()) + QLatin1Char('\n') +
                        krcStopText(live.krc.last_stop) + QLatin1Char('\n') +
                        tr("Late answers counted this session: %1. Override: %2 %.")
                            .arg(live.krc.delay)
                            .arg(live.krc.override_pct, 0, 'f', 0));
    krc_state_->setToolTip(tr("Simulated controller: %1; last stop: %2")
                               .arg(QLatin1String(xmate::sim::toString(live.krc.state)),
                                    QLatin1String(xmate::sim::toString(live.krc.last_stop))));
  }
}

}  // namespace rci::ui
