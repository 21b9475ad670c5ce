// SPDX-License-Identifier: Apache-2.0
// Collision panel: per-joint collision thresholds (setCollisionBehavior, within the SPEC maxima)
// and live bars of |external joint torque| against each threshold.
#pragma once

#include <QList>

#include <array>

#include "panels/panel_base.h"

class QDoubleSpinBox;
class QLabel;
class QProgressBar;

namespace rci::ui {

class MessageLine;

class CollisionPanel : public PanelBase {
  Q_OBJECT
 public:
  CollisionPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;

 private:
  void apply();
  void showModel();
  std::array<double, 7> thresholds() const;
  double barThreshold(int joint) const;  // what the bar of a joint is measured against, Nm

  QList<QDoubleSpinBox*> fields_;
  std::array<QLabel*, 7> names_{};
  std::array<QProgressBar*, 7> bars_{};
  std::array<const char*, 7> bar_colors_{};
  MessageLine* message_ = nullptr;
};

}  // namespace rci::ui
