// SPDX-License-Identifier: Apache-2.0
// Jog panel: press-and-hold buttons for joint +/- per joint and Cartesian +/- (x, y, z, rx, ry, rz)
// with a speed slider. Each press runs one ramped jog motion on the arm (Session::runArmMotion),
// within what the arm can reach (on RSI, the context's correction limits): the Cartesian jog through
// the controller's Cartesian control where the arm has one (Capability::kCartesianMotion), through
// the admittance guide otherwise.
#pragma once

#include <QList>

#include <array>
#include <memory>

#include "panels/panel_base.h"

class QLabel;
class QPushButton;
class QSlider;

namespace xmate::jog {
struct JogFlags;
struct JointLimitsRad;
}  // namespace xmate::jog

namespace rci::ui {

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
  std::shared_ptr<xmate::jog::JogFlags> active_;  // the jog whose button is held (or ramping down)
};

}  // namespace rci::ui
