// SPDX-License-Identifier: Apache-2.0
// IO panel: output switches set the arm's outputs through Session::runOnArm; input lamps show the
// polled inputs. The signals are the open arm's (rebuilt when a session opens).
#include "panels/io_panel.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayoutItem>
#include <QVBoxLayout>

#include <algorithm>

#include "model/signal_names.h"
#include "panels/lamp.h"
#include "session/session.h"

namespace rci::ui {
namespace {

std::vector<QString> toQt(const std::vector<std::string>& names) {
  std::vector<QString> out;
  out.reserve(names.size());
  for (const auto& n : names) out.push_back(QString::fromStdString(n));
  return out;
}

// The signals before any session opened: the default target's (an xMate's six).
std::vector<QString> defaultNames(bool output) {
  std::vector<QString> out;
  for (int i = 0; i < xmate::model::kXmateSignalCount; ++i)
    out.push_back(QString::fromStdString(output ? xmate::model::doName(xmate::model::RobotFamily::kXmate, i)
                                                : xmate::model::diName(xmate::model::RobotFamily::kXmate, i)));
  return out;
}

void clearGrid(QGridLayout* grid) {
  while (QLayoutItem* item = grid->takeAt(0)) {
    if (QLayout* inner = item->layout()) {
      while (QLayoutItem* sub = inner->takeAt(0)) {
        delete sub->widget();
        delete sub;
      }
    }
    delete item->widget();
    delete item;
  }
}

bool bit(uint64_t bits, int k) { return k >= 0 && k < 64 && ((bits >> k) & 1u) != 0; }

}  // namespace

// LiveState::outputs / inputs hold either family's signals (the session fills them).
bool outputOn(const LiveState& live, int k) { return bit(live.outputs, k); }

bool inputOn(const LiveState& live, int k) { return bit(live.inputs, k); }

IoPanel::IoPanel(Session& session, QWidget* parent) : PanelBase(session, QStringLiteral("io"), tr("IO"), parent) {
  setNeeds(uint32_t(xmate::arm::Capability::kDigitalIo));
  outs_ = new QGroupBox(tr("Digital outputs"), this);
  auto* outs_layout = new QVBoxLayout(outs_);
  outs_layout->setContentsMargins(0, 0, 0, 0);
  // The switches change with each session: their area is the widget enabled only while one is open.
  out_area_ = new QWidget(outs_);
  out_area_->setObjectName(QStringLiteral("io.outputs"));
  outs_layout->addWidget(out_area_);
  out_grid_ = new QGridLayout(out_area_);
  addSendWidget(out_area_);
  ins_ = new QGroupBox(tr("Digital inputs"), this);
  in_grid_ = new QGridLayout(ins_);
  body()->addWidget(outs_);
  body()->addWidget(ins_);
  if (xmate::arm::Arm* arm = session.arm())
    rebuild(toQt(arm->outputNames()), toQt(arm->inputNames()));
  else
    rebuild(defaultNames(true), defaultNames(false));
}

void IoPanel::rebuild(const std::vector<QString>& out_names, const std::vector<QString>& in_names) {
  clearGrid(out_grid_);
  clearGrid(in_grid_);
  outputs_.clear();
  inputs_.clear();
  sent_.clear();
  pending_.assign(out_names.size(), 0);
  const int columns = 3;  // "$OUT[12]" switches fit a narrow dock three abreast
  for (int c = 0; c < 4; ++c) {
    out_grid_->setColumnStretch(c, c < columns ? 1 : 0);
    in_grid_->setColumnStretch(c, c < columns ? 1 : 0);
  }
  for (size_t k = 0; k < out_names.size(); ++k) {
    const int i = int(k);
    const QString& name = out_names[k];
    auto* box = new QCheckBox(name, out_area_);
    box->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);  // the whole widget is clickable
    box->setObjectName(QStringLiteral("io.do%1").arg(i));
    box->setToolTip(tr("Switch output %1").arg(name));
    out_grid_->addWidget(box, i / columns, i % columns);
    outputs_.push_back(box);
    // clicked (not toggled): only the user's clicks send, not the display updates.
    connect(box, &QCheckBox::clicked, this, [this, i](bool on) { setOutput(i, on); });
  }
  if (out_names.empty())
    out_grid_->addWidget(new QLabel(tr("The robot offers no digital outputs to this PC."), out_area_), 0, 0, 1, columns);
  for (size_t k = 0; k < in_names.size(); ++k) {
    const int i = int(k);
    const QString& name = in_names[k];
    auto* lamp = new Lamp(lampGreen(), ins_);
    lamp->setObjectName(QStringLiteral("io.di%1").arg(i));
    lamp->setToolTip(tr("Level of input %1 (read about 5 times a second)").arg(name));
    auto* cell = new QHBoxLayout;  // lamp and name, in the same columns as the outputs
    cell->addWidget(lamp);
    cell->addWidget(new QLabel(name, ins_), 1);
    in_grid_->addLayout(cell, i / columns, i % columns);
    inputs_.push_back(lamp);
  }
  if (in_names.empty())
    in_grid_->addWidget(new QLabel(tr("The robot offers no digital inputs to this PC."), ins_), 0, 0, 1, columns);
}

void IoPanel::setOutput(int index, bool on) {
  if (index < 0 || index >= int(outputs_.size())) return;
  const QString name = outputs_[size_t(index)]->text();
  const QString action = tr("%1 %2").arg(name, on ? tr("on") : tr("off"));
  if (!isOpen()) {
    showStatus(action + tr(": not connected -- connect to a robot or the simulator first."), true);
    return;
  }
  if (session().isReconnecting()) {
    showStatus(action + tr(": not sent -- the connection is being re-established; try again when the status bar "
                           "shows the robot again."),
               true);
    return;
  }
  ++pending_[size_t(index)];
  sent_.push_back({action, index, on});
  showStatus(action + QStringLiteral(" ..."), false);
  const size_t signal = size_t(index);
  session().runOnArm(title() + QStringLiteral(": ") + action,
                     [signal, on](xmate::arm::Arm& arm) { arm.setOutput(signal, on); });
}

void IoPanel::commandDone(const QString& action, bool ok, const QString&) {
  for (auto it = sent_.begin(); it != sent_.end(); ++it) {
    if (it->action != action) continue;
    // A robot cannot report its outputs: the session keeps what was set (the simulators report their own).
    if (ok) session().recordDigitalOutput(it->index, it->on);
    // The switch follows live() again once no change of that output is outstanding; after a
    // refusal that puts it back where the output really is.
    if (it->index < int(pending_.size())) pending_[size_t(it->index)] = std::max(0, pending_[size_t(it->index)] - 1);
    sent_.erase(it);
    break;
  }
}

void IoPanel::refresh(const LiveState& live) {
  for (size_t i = 0; i < inputs_.size(); ++i) inputs_[i]->setOn(inputOn(live, int(i)));
  for (size_t i = 0; i < outputs_.size(); ++i)
    if (pending_[i] == 0) outputs_[i]->setChecked(outputOn(live, int(i)));
}

void IoPanel::sessionOpened() {
  if (xmate::arm::Arm* arm = session().arm()) rebuild(toQt(arm->outputNames()), toQt(arm->inputNames()));
}

void IoPanel::sessionClosed() {
  std::fill(pending_.begin(), pending_.end(), 0);
  sent_.clear();
  for (auto* lamp : inputs_) lamp->setOn(false);
}

}  // namespace rci::ui
