// SPDX-License-Identifier: Apache-2.0
// Names of robot models and session targets as the window shows them (session.h).
#include "session/session.h"

#include <QFileInfo>

#include <stdexcept>

namespace rci::ui {

QString modelName(xmate::XmateType type) {
  switch (type) {
    case xmate::XMATE3_PRO: return QStringLiteral("xMate3 Pro");
    case xmate::XMATE7_PRO: return QStringLiteral("xMate7 Pro");
    case xmate::XMATE3: return QStringLiteral("xMate3");
    case xmate::XMATE7: return QStringLiteral("xMate7");
  }
  return QStringLiteral("unknown model");
}

bool parseModel(const QString& text, xmate::XmateType& type) {
  const QString key = text.trimmed().toLower();
  if (key == QLatin1String("xmate7_pro")) type = xmate::XMATE7_PRO;
  else if (key == QLatin1String("xmate3_pro")) type = xmate::XMATE3_PRO;
  else if (key == QLatin1String("xmate7")) type = xmate::XMATE7;
  else if (key == QLatin1String("xmate3")) type = xmate::XMATE3;
  else return false;
  return true;
}

const xmate::model::RobotSpec& SessionTarget::spec() const {
  if (!isKuka()) return xmate::model::robotSpec(type);
  const xmate::model::RobotSpec* found = xmate::model::findRobotSpec(kuka_model.toStdString());
  if (!found || found->family != xmate::model::RobotFamily::kKuka)
    throw std::invalid_argument("unknown KUKA model \"" + kuka_model.toStdString() + "\" (kr6_r900_sixx, kr16_2)");
  return *found;
}

QString SessionTarget::describe() const {
  switch (kind) {
    case Kind::kSimulator: return QStringLiteral("Simulator (%1)").arg(modelName(type));
    case Kind::kRobot: return QStringLiteral("Robot %1:%2 (%3)").arg(host).arg(port).arg(modelName(type));
    default: break;
  }
  const xmate::model::RobotSpec* found = xmate::model::findRobotSpec(kuka_model.toStdString());
  const QString model = found ? QString::fromUtf8(found->display_name.data(), qsizetype(found->display_name.size()))
                              : kuka_model;
  if (kind == Kind::kKukaSimulator) return QStringLiteral("KUKA simulator (%1)").arg(model);
  return QStringLiteral("KUKA over RSI, %1 (%2)").arg(QFileInfo(rsi_config).fileName(), model);
}

}  // namespace rci::ui
