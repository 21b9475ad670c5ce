// SPDX-License-Identifier: Apache-2.0
// Soft joint limits panel: per-joint upper/lower limits in degrees within the hardware range,
// on/off and auto-limit (setJointLimit); records them in the session's operator settings.
#pragma once

#include <QList>

#include <array>

#include "panels/panel_base.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;

namespace rci::ui {

class MessageLine;

class SoftLimitsPanel : public PanelBase {
  Q_OBJECT
 public:
  SoftLimitsPanel(Session& session, QWidget* parent);

 protected:
  void sessionOpened() override;

 private:
  void apply();
  void showModel();
  void resetToHardware();

  QList<QDoubleSpinBox*> upper_, lower_;
  std::array<QLabel*, 7> names_{};
  QCheckBox* enabled_ = nullptr;
  QCheckBox* auto_limit_ = nullptr;
  MessageLine* message_ = nullptr;
};

}  // namespace rci::ui
