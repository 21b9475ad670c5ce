// SPDX-License-Identifier: Apache-2.0
// Tool & payload panel: the TCP frame relative to the flange (x, y, z, rx, ry, rz -> 4x4, setCoor)
// and the payload (mass, centre of mass, inertia; setLoad).
#pragma once

#include <QList>

#include <array>

#include "panels/panel_base.h"

class QDoubleSpinBox;
class QGroupBox;

namespace rci::ui {

class MessageLine;

// Row-major 4x4 from a translation (m) and fixed-axis angles in degrees: R = Rz(rz) Ry(ry) Rx(rx).
std::array<double, 16> toolFrameFromXyzRpy(const std::array<double, 6>& xyz_rpy_deg);

class ToolPanel : public PanelBase {
  Q_OBJECT
 public:
  ToolPanel(Session& session, QWidget* parent);

 private:
  QGroupBox* makeToolGroup();
  QGroupBox* makePayloadGroup();
  void applyTool();
  void applyPayload();

  QList<QDoubleSpinBox*> tool_;     // x, y, z (m), rx, ry, rz (deg)
  QDoubleSpinBox* mass_ = nullptr;  // kg
  QList<QDoubleSpinBox*> centre_;   // m, flange frame
  QList<QDoubleSpinBox*> inertia_;  // Ixx, Iyy, Izz, Ixy, Ixz, Iyz (kg m^2)
  MessageLine* tool_message_ = nullptr;
  MessageLine* payload_message_ = nullptr;
};

}  // namespace rci::ui
