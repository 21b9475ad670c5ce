// SPDX-License-Identifier: Apache-2.0
// RSI panel (KUKA): what the RSI session is doing (running, cycle, late answers, answer time), the
// RSI context and Ethernet config it runs (objects, correction limits, the RSI start pose, the
// listen address, the values exchanged each cycle) and the technology values and messages.
// Read-only: it sends nothing. Laid out in collapsible sections for a narrow dock.
#pragma once

#include <QString>

#include <array>

#include "panels/panel_base.h"

class QLabel;
class QToolButton;
class QTreeWidget;

namespace xmate::arm {
class RsiArm;
}

namespace rci::ui {

class Lamp;

class RsiPanel : public PanelBase {
  Q_OBJECT
 public:
  // GUI thread.
  RsiPanel(Session& session, QWidget* parent);
  // The session has an RSI arm (a KUKA). GUI thread.
  bool appliesTo(Session& session) const override;

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;

 private:
  // A titled section whose content the operator shows or hides (remembered under "open.<name>").
  QWidget* addSection(const QString& name, const QString& title, QWidget* content, bool open_by_default);
  QWidget* makeState();
  QWidget* makeFiles();
  QWidget* makeLimits();
  QWidget* makeObjects();
  QWidget* makeChannels();
  QWidget* makeTech();
  void showFiles(xmate::arm::RsiArm& arm);
  void showLimits(xmate::arm::RsiArm& arm);
  void showObjects(xmate::arm::RsiArm& arm);
  void showChannels(xmate::arm::RsiArm& arm);
  void showTech(xmate::arm::RsiArm& arm, const LiveState& live);

  // Session
  Lamp* lamp_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* cycle_ = nullptr;
  QLabel* delay_ = nullptr;
  QLabel* in_a_row_ = nullptr;
  QLabel* late_answers_ = nullptr;
  QLabel* answer_p99_ = nullptr;
  QLabel* refused_ = nullptr;
  // Files
  QLabel* context_file_ = nullptr;
  QLabel* config_file_ = nullptr;
  QLabel* listen_ = nullptr;
  // Limits
  std::array<QLabel*, 6> lower_{}, upper_{}, start_{};
  QLabel* timeout_ = nullptr;
  QLabel* limits_note_ = nullptr;
  // Objects, channels
  QTreeWidget* objects_ = nullptr;
  QTreeWidget* channels_ = nullptr;
  QToolButton* objects_header_ = nullptr;
  // Technology values and messages
  QLabel* tech_ = nullptr;
  QLabel* messages_ = nullptr;
  QString shown_tech_;
};

}  // namespace rci::ui
