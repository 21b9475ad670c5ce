// SPDX-License-Identifier: Apache-2.0
// Jog panel: press-and-hold buttons for joint +/- per joint and Cartesian +/- (x, y, z, rx, ry, rz)
// with a speed slider. Each press runs one ramped jog motion: on an xMate through
// Session::runMotion(); the joint jog of any other arm (a KUKA over RSI) through
// Session::runArmMotion(), within the RSI context's correction limits. The Cartesian jog needs the
// xMate's Cartesian control and is disabled otherwise.
#pragma once

#include <QList>

#include <array>
#include <memory>

#include "panels/panel_base.h"

class QLabel;
class QPushButton;
class QSlider;

namespace rci::ui {

struct JogFlags;
struct JointLimitsRad;

class JogPanel : public PanelBase {
  Q_OBJECT
 public:
  JogPanel(Session& session, QWidget* parent);
  ~JogPanel() override;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;
  void changeEvent(QEvent* event) override;
  void hideEvent(QHideEvent* event) override;

 private:
  QWidget* makeJointGroup();
  QWidget* makeCartesianGroup();
  QPushButton* makeJogButton(const QString& name, const QString& text, const QString& tip, bool cartesian, int axis,
                             int direction, QWidget* parent);
  void press(bool cartesian, int axis, int direction, const QString& what);
  // The joint jog on the session's arm::Arm (runArmMotion).
  // A jog on an arm::Arm (a KUKA): an axis (JointJog) or the flange along / about a base axis (JogPush
  // through the admittance guide), within the RSI correction limits.
  void pressArm(bool cartesian, int axis, int direction, const QString& label, const JointLimitsRad& limits,
                double speed);
  void release();
  void showModel();
  double speedFraction() const;

  QSlider* speed_ = nullptr;
  QLabel* speed_label_ = nullptr;
  QList<QWidget*> joint_rows_[7];
  std::array<QLabel*, 7> joint_names_{};
  QWidget* cartesian_group_ = nullptr;
  QLabel* hint_ = nullptr;
  std::array<QLabel*, 7> angles_{};
  std::shared_ptr<JogFlags> active_;  // the jog whose button is held (or ramping down)
};

}  // namespace rci::ui
