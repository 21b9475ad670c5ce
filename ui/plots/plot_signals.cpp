// SPDX-License-Identifier: Apache-2.0
// Names and units of the plotted signals (plot_signals.h).
#include "plots/plot_signals.h"

namespace rci::ui::plots {

Quantity quantityOf(Signal signal) {
  switch (signal) {
    case Signal::kPositionMeasured:
    case Signal::kPositionCommanded: return Quantity::kPosition;
    case Signal::kVelocityMeasured: return Quantity::kVelocity;
    default: return Quantity::kTorque;
  }
}

QString quantityTitle(Quantity quantity) {
  switch (quantity) {
    case Quantity::kPosition: return QStringLiteral("Joint position");
    case Quantity::kVelocity: return QStringLiteral("Joint velocity");
    default: return QStringLiteral("Joint torque");
  }
}

QString quantityUnit(Quantity quantity) {
  switch (quantity) {
    case Quantity::kPosition: return QStringLiteral("rad");
    case Quantity::kVelocity: return QStringLiteral("rad/s");
    default: return QStringLiteral("Nm");
  }
}

QString signalLabel(Signal signal) {
  switch (signal) {
    case Signal::kPositionCommanded:
    case Signal::kTorqueCommanded: return QStringLiteral("commanded");
    case Signal::kTorqueExternal: return QStringLiteral("external");
    default: return QStringLiteral("measured");
  }
}

QString signalKey(Signal signal) {
  switch (signal) {
    case Signal::kPositionMeasured: return QStringLiteral("q");
    case Signal::kPositionCommanded: return QStringLiteral("q_c");
    case Signal::kVelocityMeasured: return QStringLiteral("dq");
    case Signal::kTorqueMeasured: return QStringLiteral("tau");
    case Signal::kTorqueCommanded: return QStringLiteral("tau_c");
    default: return QStringLiteral("tau_ext");
  }
}

}  // namespace rci::ui::plots
