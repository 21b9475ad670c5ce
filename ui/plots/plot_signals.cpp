// SPDX-License-Identifier: Apache-2.0
// Names and units of the plotted signals (plot_signals.h).
#include "plots/plot_signals.h"

namespace rci::ui::plots {

Quantity quantityOf(Signal signal) {
  switch (signal) {
    case Signal::kPositionMeasured:
    case Signal::kPositionCommanded:
    case Signal::kAxisActual:
    case Signal::kAxisSetPoint: return Quantity::kPosition;
    case Signal::kVelocityMeasured:
    case Signal::kAxisVelocity: return Quantity::kVelocity;
    case Signal::kMotorCurrent: return Quantity::kMotorCurrent;
    case Signal::kSensorForce:
    case Signal::kSensorTorque: return Quantity::kForce;
    case Signal::kLateAnswers: return Quantity::kDelay;
    case Signal::kTcpActual:
    case Signal::kTcpSetPoint: return Quantity::kTcp;
    default: return Quantity::kTorque;
  }
}

QString quantityTitle(Quantity quantity) {
  switch (quantity) {
    case Quantity::kPosition: return QStringLiteral("Joint position");
    case Quantity::kVelocity: return QStringLiteral("Joint velocity");
    case Quantity::kMotorCurrent: return QStringLiteral("Motor current");
    case Quantity::kForce: return QStringLiteral("Force sensor");
    case Quantity::kDelay: return QStringLiteral("Late answers");
    case Quantity::kTcp: return QStringLiteral("TCP position");
    default: return QStringLiteral("Joint torque");
  }
}

QString quantityUnit(Quantity quantity) {
  switch (quantity) {
    case Quantity::kPosition: return QStringLiteral("rad");
    case Quantity::kVelocity: return QStringLiteral("rad/s");
    case Quantity::kMotorCurrent: return QStringLiteral("A");
    case Quantity::kForce: return QStringLiteral("N, Nm");
    case Quantity::kDelay: return QStringLiteral("count");
    case Quantity::kTcp: return QStringLiteral("m");
    default: return QStringLiteral("Nm");
  }
}

bool quantityCollapses(Quantity quantity) { return static_cast<int>(quantity) >= kQuantityCount; }

QString signalLabel(Signal signal) {
  switch (signal) {
    case Signal::kPositionCommanded:
    case Signal::kTorqueCommanded: return QStringLiteral("commanded");
    case Signal::kTorqueExternal: return QStringLiteral("external");
    case Signal::kAxisActual:
    case Signal::kAxisVelocity: return QStringLiteral("actual");
    case Signal::kAxisSetPoint:
    case Signal::kTcpSetPoint: return QStringLiteral("set-point");
    case Signal::kTcpActual: return QStringLiteral("actual");
    case Signal::kGearTorque: return QStringLiteral("gear");
    case Signal::kMotorCurrent: return QStringLiteral("motor");
    case Signal::kSensorForce: return QStringLiteral("force");
    case Signal::kSensorTorque: return QStringLiteral("torque");
    case Signal::kLateAnswers: return QStringLiteral("late answers");
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
    case Signal::kTorqueExternal: return QStringLiteral("tau_ext");
    case Signal::kAxisActual: return QStringLiteral("q");
    case Signal::kAxisSetPoint: return QStringLiteral("q_set");
    case Signal::kAxisVelocity: return QStringLiteral("dq");
    case Signal::kGearTorque: return QStringLiteral("tau_gear");
    case Signal::kMotorCurrent: return QStringLiteral("current");
    case Signal::kSensorForce:
    case Signal::kSensorTorque: return QStringLiteral("ft");
    case Signal::kTcpActual: return QStringLiteral("tcp");
    case Signal::kTcpSetPoint: return QStringLiteral("tcp_set");
    default: return QStringLiteral("rsi_late_answers");
  }
}

QString signalUnit(Signal signal) {
  switch (signal) {
    case Signal::kSensorForce: return QStringLiteral("N");
    case Signal::kSensorTorque: return QStringLiteral("Nm");
    case Signal::kLateAnswers: return QString();
    default: return quantityUnit(quantityOf(signal));
  }
}

bool isJointSignal(Signal signal) {
  return signal != Signal::kSensorForce && signal != Signal::kSensorTorque && signal != Signal::kLateAnswers &&
         signal != Signal::kTcpActual && signal != Signal::kTcpSetPoint;
}

int componentCount(Signal signal) {
  if (isJointSignal(signal)) return kJointCount;
  return signal == Signal::kLateAnswers ? 1 : 3;
}

QString componentName(Signal signal, int component) {
  static const char axes[] = {'x', 'y', 'z'};
  if (component < 0 || component >= 3) return QString();
  switch (signal) {
    case Signal::kSensorForce: return QStringLiteral("F") + QLatin1Char(axes[component]);
    case Signal::kSensorTorque: return QStringLiteral("T") + QLatin1Char(axes[component]);
    case Signal::kTcpActual:
    case Signal::kTcpSetPoint: return QString(QLatin1Char(axes[component])).toUpper();
    default: return QString();
  }
}

}  // namespace rci::ui::plots
