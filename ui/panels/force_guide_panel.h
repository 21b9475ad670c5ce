// SPDX-License-Identifier: Apache-2.0
// Hand guiding through the F/T sensor on the flange (a KUKA has no hand guiding of its own): which
// motions the hand may guide, the virtual mass and damping, the speed cap and the tool's weight;
// start / stop, and what the guide does (force, speed, an axis held at its limit, why it ended).
#pragma once

#include <memory>

#include "panels/panel_base.h"

class QComboBox;
class QLabel;
class QPushButton;

namespace rci::ui {

class Lamp;
class MessageLine;
struct ForceGuide;  // the guide and its sensor source (force_guide_panel.cpp)

class ForceGuidePanel : public PanelBase {
  Q_OBJECT
 public:
  ForceGuidePanel(Session& session, QWidget* parent);
  ~ForceGuidePanel() override;

  // A KUKA whose session has an F/T sensor (Session::forceSensor()).
  bool appliesTo(Session& session) const override;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;

 private:
  void start();
  void stop();
  void showGuideStatus();
  // Start while connected and no motion runs, Stop while this panel's guide runs.
  void updateButtons();

  QComboBox* axes_ = nullptr;  // data: GuideAxes
  QDoubleSpinBox* mass_ = nullptr;
  QDoubleSpinBox* damping_ = nullptr;
  QDoubleSpinBox* speed_ = nullptr;       // mm/s
  QDoubleSpinBox* dead_band_ = nullptr;   // N
  QDoubleSpinBox* tool_mass_ = nullptr;   // kg
  QList<QDoubleSpinBox*> tool_center_;    // mm, flange frame
  QPushButton* start_ = nullptr;
  QPushButton* stop_ = nullptr;
  Lamp* lamp_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* detail_ = nullptr;
  MessageLine* message_ = nullptr;
  // The running guide (shared with the motion job); null when none ran this session.
  std::shared_ptr<ForceGuide> guide_;
  bool guiding_ = false;
};

}  // namespace rci::ui
