// SPDX-License-Identifier: Apache-2.0
// Drag panel: hand guiding -- space (joint / Cartesian), type (translation / rotation / free),
// start / stop (startDrag / stopDrag), and whether the robot is being guided.
#pragma once

#include "panels/panel_base.h"

class QComboBox;
class QLabel;

namespace rci::ui {

class Lamp;
class MessageLine;

class DragPanel : public PanelBase {
  Q_OBJECT
 public:
  DragPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionClosed() override;

 private:
  void start();
  void spaceChanged();

  QComboBox* space_ = nullptr;  // data: 1 joint, 2 Cartesian
  QComboBox* type_ = nullptr;   // data: 1 translation, 2 rotation, 3 free
  Lamp* lamp_ = nullptr;
  QLabel* state_ = nullptr;
  MessageLine* message_ = nullptr;
};

}  // namespace rci::ui
