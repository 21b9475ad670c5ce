// SPDX-License-Identifier: Apache-2.0
// Simulator panel (built-in simulator only): push the arm with an external wrench, press the
// e-stop or guard stop, set DI levels, DO->DI loop-back. Disabled on a real robot.
#pragma once

#include <QList>

#include <array>
#include <functional>

#include "panels/panel_base.h"

class QCheckBox;
class QDoubleSpinBox;
class QGroupBox;
class QPushButton;

namespace xmate::sim { class Server; }

namespace rci::ui {

class MessageLine;

class SimulatorPanel : public PanelBase {
  Q_OBJECT
 public:
  SimulatorPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;

 private:
  QGroupBox* makeWrenchGroup();
  QGroupBox* makeStopsGroup();
  QGroupBox* makeInputsGroup();
  // Runs a scene call on the embedded simulator (quick, GUI thread); shows failures.
  void scene(const QString& what, const std::function<void(xmate::sim::Server&)>& call);
  void applyWrench(bool release);
  void updateAvailability();

  QList<QDoubleSpinBox*> wrench_;  // Fx, Fy, Fz (N), Mx, My, Mz (Nm)
  QPushButton* estop_ = nullptr;
  QPushButton* gstop_ = nullptr;
  std::array<QCheckBox*, 6> inputs_{};
  QCheckBox* loopback_ = nullptr;
  MessageLine* message_ = nullptr;
  QList<QWidget*> groups_;
};

}  // namespace rci::ui
