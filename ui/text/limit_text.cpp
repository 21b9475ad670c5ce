// SPDX-License-Identifier: Apache-2.0
// Operator text for joints beyond their limits and the TCP outside the safety box, from the live
// state and the limits the window set (operator_text.h).
#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

#include "model/robot_spec.h"
#include "session/session.h"
#include "text/operator_text.h"

namespace rci::ui::text {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("OperatorText", text); }

constexpr double kDegPerRad = 57.295779513082320876798;
const QString kMinus = QStringLiteral("\u2212");  // as on the jog buttons

// "120.7° > 120.0°", with a second decimal where one would show two equal numbers.
QString comparison(double value, double limit, bool upper) {
  int decimals = 1;
  if (QString::number(value, 'f', 1) == QString::number(limit, 'f', 1)) decimals = 2;
  return QStringLiteral("%1° %2 %3°")
      .arg(QString::number(value, 'f', decimals), upper ? QStringLiteral(">") : QStringLiteral("<"),
           QString::number(limit, 'f', decimals));
}

QString amountDeg(double beyond) {
  if (beyond < 0.05) return tr("less than 0.1°");
  return QStringLiteral("%1°").arg(QString::number(beyond, 'f', 1));
}

QString limitName(const JointExcursion& e) {
  if (e.soft) return e.upper ? tr("upper soft limit") : tr("lower soft limit");
  return e.upper ? tr("upper limit") : tr("lower limit");
}

QString millimetres(double metres) {
  const double mm = metres * 1000.0;
  return mm < 1.0 ? tr("less than 1 mm") : QStringLiteral("%1 mm").arg(QString::number(mm, 'f', 0));
}

// The base axis (0..2) a unit vector lies along, with its sign; -1 if it is not along one.
int baseAxis(double x, double y, double z, int& sign) {
  const double c[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) {
    if (std::abs(c[k]) > 0.999) {
      sign = c[k] > 0 ? 1 : -1;
      return k;
    }
  }
  return -1;
}

}  // namespace

std::vector<JointExcursion> jointsBeyondLimits(const std::array<double, 7>& q, int dof, const OperatorSettings* settings,
                                               const xmate::model::RobotSpec& spec) {
  std::vector<JointExcursion> out;
  const bool soft = settings != nullptr && settings->soft_limits_enabled;
  const int n = std::min(dof, spec.dof);
  for (int i = 0; i < n && i < 7; ++i) {
    const size_t j = size_t(i);
    const double value = q[j] * kDegPerRad;
    const double upper = soft ? settings->soft_upper_deg[j] : spec.q_max[j] * kDegPerRad;
    const double lower = soft ? settings->soft_lower_deg[j] : spec.q_min[j] * kDegPerRad;
    if (value > upper) out.push_back({i, true, value, upper, soft});
    else if (value < lower) out.push_back({i, false, value, lower, soft});
  }
  return out;
}

QString describe(const JointExcursion& e) {
  return tr("J%1 reached its %2 (%3)").arg(e.joint + 1).arg(limitName(e), comparison(e.value_deg, e.limit_deg, e.upper));
}

QString remedy(const JointExcursion& e) {
  const QString button = QStringLiteral("J%1 %2").arg(e.joint + 1).arg(e.upper ? kMinus : QStringLiteral("+"));
  return tr("J%1 is %2 beyond its %3: Jog %4 or guide it back towards the range")
      .arg(e.joint + 1)
      .arg(amountDeg(e.beyondDeg()), limitName(e), button);
}

std::optional<BoxExcursion> tcpOutsideBox(const std::array<double, 16>& tcp_pose, const SafetyBox& box) {
  if (!box.enabled) return std::nullopt;
  const auto& f = box.frame;  // row-major; column k of the rotation is the box's axis k in the base frame
  const double d[3] = {tcp_pose[3] - f[3], tcp_pose[7] - f[7], tcp_pose[11] - f[11]};
  BoxExcursion e;
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double local = f[0 * 4 + k] * d[0] + f[1 * 4 + k] * d[1] + f[2 * 4 + k] * d[2];
    const double excess = std::abs(local) - 0.5 * box.size[size_t(k)];
    if (excess <= 0) continue;
    const int side = local > 0 ? 1 : -1;
    e.excess_m[size_t(k)] = excess;
    e.side[size_t(k)] = side;
    sum += excess * excess;
    // The way back is against the side crossed; named by the base axis the box axis lies along.
    int sign = 1;
    const int axis = baseAxis(f[0 * 4 + k], f[1 * 4 + k], f[2 * 4 + k], sign);
    if (axis >= 0) {
      const bool plus = -side * sign > 0;
      e.back[size_t(k)] = QStringLiteral("%1 %2").arg(QChar('x' + axis)).arg(plus ? QStringLiteral("+") : kMinus);
    }
  }
  if (sum <= 0) return std::nullopt;
  e.distance_m = std::sqrt(sum);
  return e;
}

QString describe(const BoxExcursion& e) {
  QStringList sides;
  for (size_t k = 0; k < 3; ++k) {
    if (e.side[k] == 0) continue;
    sides << QStringLiteral("%1%2").arg(e.side[k] > 0 ? QStringLiteral("+") : kMinus).arg(QChar('x' + int(k)));
  }
  return tr("The TCP is %1 outside the safety box (beyond its %2 side)")
      .arg(millimetres(e.distance_m), sides.join(tr(" and ")));
}

QString remedy(const BoxExcursion& e) {
  QStringList moves;
  for (const QString& back : e.back)
    if (!back.isEmpty()) moves << tr("TCP %1").arg(back);
  if (moves.isEmpty()) return tr("Guide or jog the TCP back towards the centre of the box");
  return tr("Move the TCP back into the box: jog %1 (Jog panel) or guide it").arg(moves.join(tr(" and ")));
}

}  // namespace rci::ui::text
