// SPDX-License-Identifier: Apache-2.0
// IO panel: the digital outputs the arm offers (switches) and its digital inputs (lamps, live) --
// an xMate's DO0_0..DO1_1 / DI0_0..DI1_1, a KUKA's $OUT[n] / $IN[n] as its RSI context wires them.
#pragma once

#include <QString>

#include <cstdint>
#include <deque>
#include <vector>

#include "panels/panel_base.h"

class QCheckBox;
class QGridLayout;
class QGroupBox;
class QLabel;

namespace rci::ui {

class Lamp;

// Whether output / input k (the index into Arm::outputNames() / inputNames()) is on in `live`
// (its outputs / inputs bits, either family). GUI thread.
bool outputOn(const LiveState& live, int k);
bool inputOn(const LiveState& live, int k);

class IoPanel : public PanelBase {
  Q_OBJECT
 public:
  IoPanel(Session& session, QWidget* parent);

 protected:
  void refresh(const LiveState& live) override;
  void sessionOpened() override;
  void sessionClosed() override;
  void commandDone(const QString& action, bool ok, const QString& message) override;

 private:
  // Replaces the switches and lamps by one per signal name (object names io.do<k> / io.di<k>).
  void rebuild(const std::vector<QString>& outputs, const std::vector<QString>& inputs);
  void setOutput(int index, bool on);

  QGroupBox* outs_ = nullptr;
  QGroupBox* ins_ = nullptr;
  QWidget* out_area_ = nullptr;  // holds the switches
  QGridLayout* out_grid_ = nullptr;
  QGridLayout* in_grid_ = nullptr;
  std::vector<QCheckBox*> outputs_;
  std::vector<Lamp*> inputs_;
  std::vector<int> pending_;  // output changes of each output not yet answered
  struct Sent {
    QString action;
    int index;
    bool on;
  };
  std::deque<Sent> sent_;  // in the order sent: recorded on success
};

}  // namespace rci::ui
