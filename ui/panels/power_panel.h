// SPDX-License-Identifier: Apache-2.0
// Power panel: motor power on/off with the motor-state lamp, and reboot of the controller.
#pragma once

#include "panels/panel_base.h"

class QLabel;
class QPushButton;

namespace rci::ui {

class Lamp;

class PowerPanel : public PanelBase {
  Q_OBJECT
 public:
  PowerPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionClosed() override;

 private:
  void rebootWithConfirmation();

  Lamp* motor_lamp_ = nullptr;
  QLabel* motor_text_ = nullptr;
};

}  // namespace rci::ui
