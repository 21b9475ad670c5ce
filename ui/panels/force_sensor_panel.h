// SPDX-License-Identifier: Apache-2.0
// Force sensor panel (KUKA hand guiding's F/T sensor): the live wrench (Fx Fy Fz N, Tx Ty Tz Nm, as
// numbers and bars), whether readings arrive and what to check when they do not, the sensor's
// address, its status word when it reports a problem, and a "Bias (zero)" for this display.
#pragma once

#include <array>

#include "panels/panel_base.h"

class QLabel;
class QPushButton;

namespace rci::ui {

class Lamp;
class WrenchBar;

class ForceSensorPanel : public PanelBase {
  Q_OBJECT
 public:
  // GUI thread.
  ForceSensorPanel(Session& session, QWidget* parent);
  // The session has a force sensor. GUI thread.
  bool appliesTo(Session& session) const override;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;

 private:
  void bias();
  void clearBias();
  void showValues();
  QString address() const;

  Lamp* lamp_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* address_ = nullptr;
  QLabel* rate_ = nullptr;
  std::array<QLabel*, 6> values_{};
  std::array<WrenchBar*, 6> bars_{};
  QPushButton* bias_button_ = nullptr;
  QPushButton* clear_button_ = nullptr;
  QLabel* bias_note_ = nullptr;
  // The newest healthy reading (sensor frame) and the display's zero taken at "Bias (zero)".
  bool have_reading_ = false;
  std::array<double, 6> reading_{};
  bool biased_ = false;
  std::array<double, 6> bias_{};
};

}  // namespace rci::ui
