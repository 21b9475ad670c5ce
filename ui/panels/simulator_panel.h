// SPDX-License-Identifier: Apache-2.0
// Simulator panel (built-in simulators only). The xMate simulator: push the arm with an external
// wrench, press the e-stop or guard stop, set DI levels, DO->DI loop-back. The KUKA simulator: push
// the flange (the simulated F/T sensor reads it), set $IN[n], the override, and the RSI faults
// (answers lost or late, RSI off for a while) with the simulated controller's state.
#pragma once

#include <QList>

#include <array>
#include <functional>
#include <vector>

#include "panels/panel_base.h"

class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QGroupBox;
class QLabel;
class QPushButton;

namespace xmate::sim {
class Krc;
class Server;
}

namespace rci::ui {

class MessageLine;

class SimulatorPanel : public PanelBase {
  Q_OBJECT
 public:
  SimulatorPanel(Session& session, QWidget* parent);
  // Shown for the built-in xMate simulator and the built-in KUKA simulator. GUI thread.
  bool appliesTo(Session& session) const override;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;

 private:
  QGroupBox* makeWrenchGroup();
  QGroupBox* makeStopsGroup();
  QGroupBox* makeInputsGroup();
  QGroupBox* makeKukaInputsGroup();
  QGroupBox* makeOverrideGroup();
  QGroupBox* makeFaultsGroup();
  // Runs a scene call on the embedded simulator (quick, GUI thread); shows failures.
  void scene(const QString& what, const std::function<void(xmate::sim::Server&)>& call);
  void kukaScene(const QString& what, const std::function<void(xmate::sim::Krc&)>& call);
  void runScene(const QString& what, bool available, const std::function<void()>& call);
  void applyWrench(bool release);
  void rebuildKukaInputs();
  void updateAvailability();

  QGroupBox* wrench_group_ = nullptr;
  QList<QDoubleSpinBox*> wrench_;  // Fx, Fy, Fz (N), Mx, My, Mz (Nm)
  QPushButton* estop_ = nullptr;
  QPushButton* gstop_ = nullptr;
  std::array<QCheckBox*, 6> inputs_{};
  QCheckBox* loopback_ = nullptr;
  // KUKA simulator
  QGridLayout* kuka_inputs_grid_ = nullptr;
  QWidget* kuka_inputs_area_ = nullptr;
  std::vector<QCheckBox*> kuka_inputs_;
  std::vector<int> kuka_input_signals_;  // $IN number of each box
  QDoubleSpinBox* override_ = nullptr;
  QDoubleSpinBox* drop_cycles_ = nullptr;
  QDoubleSpinBox* delay_cycles_ = nullptr;
  QDoubleSpinBox* suspend_seconds_ = nullptr;
  QLabel* faults_help_ = nullptr;
  QLabel* krc_state_ = nullptr;

  QLabel* note_ = nullptr;
  MessageLine* message_ = nullptr;
  QList<QWidget*> xmate_groups_;  // shown for the xMate simulator
  QList<QWidget*> kuka_groups_;   // shown for the KUKA simulator
  bool showing_kuka_ = false;
};

}  // namespace rci::ui
