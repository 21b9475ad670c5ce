// SPDX-License-Identifier: Apache-2.0
// Cartesian safety box panel: size, centre and on/off of the box the TCP must stay in
// (setCartesianLimit); records the box in the session's operator settings for the 3D view.
#pragma once

#include <QList>

#include "panels/panel_base.h"

class QCheckBox;
class QDoubleSpinBox;

namespace rci::ui {

class MessageLine;

class SafetyBoxPanel : public PanelBase {
  Q_OBJECT
 public:
  SafetyBoxPanel(Session& session, QWidget* parent);

 private:
  void apply();
  void centreOnTcp();

  QList<QDoubleSpinBox*> size_;    // x, y, z edge lengths, m
  QList<QDoubleSpinBox*> centre_;  // x, y, z in the base frame, m
  QCheckBox* enabled_ = nullptr;
  MessageLine* message_ = nullptr;
};

}  // namespace rci::ui
