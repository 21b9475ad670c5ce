// SPDX-License-Identifier: Apache-2.0
// Names of robot models and session targets as the window shows them (session.h).
#include "session/session.h"

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

QString SessionTarget::describe() const {
  if (kind == Kind::kSimulator) return QStringLiteral("Simulator (%1)").arg(modelName(type));
  return QStringLiteral("Robot %1:%2 (%3)").arg(host).arg(port).arg(modelName(type));
}

}  // namespace rci::ui
