// SPDX-License-Identifier: Apache-2.0
// Safety panel: what is wrong right now, first -- active errors, stops, joints beyond their limits
// and the TCP outside the safety box, each in plain words with what to do -- and the Recover button;
// then the emergency and guard stop lamps and the robot's mode; then all 20 error conditions by
// their plain titles (collapsed; the controller's names in the tooltips).
#pragma once

#include <QString>

#include <array>
#include <cstdint>

#include "panels/panel_base.h"
#include "text/operator_text.h"

class QLabel;
class QPushButton;
class QToolButton;

namespace rci::ui {

class Lamp;

class SafetyPanel : public PanelBase {
  Q_OBJECT
 public:
  SafetyPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionClosed() override;

 private:
  QWidget* makeActive();
  QWidget* makeStops();
  QWidget* makeConditions();
  void showProblems();
  void showBits(uint32_t mask);
  void showAll(bool shown);

  QLabel* details_ = nullptr;
  QPushButton* recover_ = nullptr;
  Lamp* estop_ = nullptr;
  Lamp* gstop_ = nullptr;
  QLabel* mode_ = nullptr;
  QToolButton* show_all_ = nullptr;
  QWidget* conditions_ = nullptr;
  std::array<Lamp*, text::kErrorBitCount> bit_lamps_{};
  std::array<QLabel*, text::kErrorBitCount> bit_labels_{};
  uint32_t shown_mask_ = ~0u;
  QString shown_details_;
};

}  // namespace rci::ui
