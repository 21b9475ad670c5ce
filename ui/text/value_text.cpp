// SPDX-License-Identifier: Apache-2.0
// Operator text for values an editor refuses before sending (operator_text.h): the parameter
// checks name the call and its parameters ("setCollisionBehavior: upper_torque_thresholds_nominal[2]
// = 90 is outside (0, 60] Nm"); the window names the field the operator typed into ("J3 threshold").
#include <QCoreApplication>
#include <QRegularExpression>

#include "text/operator_text.h"

namespace rci::ui::text {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("OperatorText", text); }

QString joint(int index) { return index >= 0 ? QStringLiteral("J%1").arg(index + 1) : QString(); }

QString axisOf(int index, const char* const* names, int count) {
  return index >= 0 && index < count ? QString::fromLatin1(names[index]) : QString();
}

// "J3 threshold", or "threshold" without an element.
QString named(const QString& element, const char* what) {
  const QString name = tr(what);
  return element.isEmpty() ? name : element + QLatin1Char(' ') + name;
}

// The field a parameter (and element) of a parameter check stands for.
QString fieldName(const QString& parameter, int index) {
  static const char* const xyz[] = {"x", "y", "z"};
  static const char* const pose[] = {"x", "y", "z", "Rx", "Ry", "Rz"};
  static const char* const wrench[] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  static const char* const inertia[] = {"Ixx", "Ixy", "Ixz", "Iyx", "Iyy", "Iyz", "Izx", "Izy", "Izz"};
  if (parameter == QLatin1String("upper_torque_thresholds_nominal")) return named(joint(index), "threshold");
  if (parameter == QLatin1String("K_theta")) return named(joint(index), "stiffness");
  if (parameter == QLatin1String("K_x")) return named(axisOf(index, pose, 6), "stiffness");
  if (parameter == QLatin1String("upper")) return named(joint(index), "upper limit");
  if (parameter == QLatin1String("lower")) return named(joint(index), "lower limit");
  if (parameter == QLatin1String("tau")) return tr("desired wrench %1").arg(axisOf(index, wrench, 6)).trimmed();
  if (parameter == QLatin1String("size")) return tr("box size %1").arg(axisOf(index, xyz, 3)).trimmed();
  if (parameter == QLatin1String("center")) return tr("centre of mass %1").arg(axisOf(index, xyz, 3)).trimmed();
  if (parameter == QLatin1String("inertia")) return tr("inertia %1").arg(axisOf(index, inertia, 9)).trimmed();
  if (parameter == QLatin1String("mass")) return tr("payload mass");
  if (parameter == QLatin1String("joint_hz")) return tr("joint filter");
  if (parameter == QLatin1String("cartesian_hz")) return tr("Cartesian filter");
  if (parameter == QLatin1String("torque_hz")) return tr("torque filter");
  if (parameter == QLatin1String("F_T_EE")) return tr("the TCP frame");
  if (parameter == QLatin1String("frame")) return tr("the box frame");
  if (parameter == QLatin1String("drag_space")) return tr("drag space");
  if (parameter == QLatin1String("drag_type")) return tr("drag type");
  return {};
}

}  // namespace

QString valueRefusal(const std::string& raw) {
  QString rest = QString::fromStdString(raw).trimmed();
  static const QRegularExpression call(QStringLiteral(R"(^[A-Za-z_]+: )"));
  if (const auto m = call.match(rest); m.hasMatch()) rest = rest.mid(m.capturedLength());
  // Every parameter (with its element) by the field's name.
  static const QRegularExpression parameter(QStringLiteral(R"(\b([A-Za-z_]+)(\[(\d+)\])?)"));
  QString out;
  qsizetype at = 0;
  for (auto it = parameter.globalMatch(rest); it.hasNext();) {
    const auto m = it.next();
    // A parameter, not a word of the sentence: the first word, one with an element or an underscore.
    const QString word = m.captured(1);
    if (m.capturedStart() != 0 && m.captured(3).isEmpty() && !word.contains(QLatin1Char('_'))) continue;
    const QString name = fieldName(word, m.captured(3).isEmpty() ? -1 : m.captured(3).toInt());
    if (name.isEmpty()) continue;
    out += rest.mid(at, m.capturedStart() - at) + name;
    at = m.capturedEnd();
  }
  out += rest.mid(at);
  if (!out.isEmpty()) out[0] = out[0].toUpper();
  return out;
}

}  // namespace rci::ui::text
