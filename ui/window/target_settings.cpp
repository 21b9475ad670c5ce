// SPDX-License-Identifier: Apache-2.0
// Target persistence and parsing for the connection bar (target_settings.h).
#include "window/target_settings.h"

#include <QFileInfo>
#include <QSettings>

#include <xmate/ini.h>

namespace rci::ui {
namespace {

constexpr int kMaxRecent = 8;

QSettings settings() { return QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")); }

}  // namespace

bool parseHostPort(const QString& text, QString& host, quint16& port, QString& error) {
  const QString trimmed = text.trimmed();
  const int colon = trimmed.lastIndexOf(QLatin1Char(':'));
  if (trimmed.isEmpty() || colon <= 0 || colon == trimmed.size() - 1) {
    error = QStringLiteral("\"%1\" is not a robot address. Enter it as HOST:PORT, e.g. 192.168.0.160:1337.")
                .arg(trimmed);
    return false;
  }
  bool ok = false;
  const uint value = trimmed.mid(colon + 1).toUInt(&ok);
  if (!ok || value == 0 || value > 65535) {
    error = QStringLiteral("\"%1\" is not a port. Use a number from 1 to 65535 (the RCI default is 1337).")
                .arg(trimmed.mid(colon + 1));
    return false;
  }
  const QString name = trimmed.left(colon);
  if (name.contains(QLatin1Char(' '))) {
    error = QStringLiteral("\"%1\" is not a host name or IP address (it contains a space).").arg(name);
    return false;
  }
  host = name;
  port = quint16(value);
  return true;
}

QStringList recentRobots() { return settings().value(QStringLiteral("connection/recent")).toStringList(); }

void rememberRobot(const QString& host_port) {
  QStringList list = recentRobots();
  list.removeAll(host_port);
  list.prepend(host_port);
  while (list.size() > kMaxRecent) list.removeLast();
  settings().setValue(QStringLiteral("connection/recent"), list);
}

std::optional<SessionTarget> lastTarget() {
  QSettings s = settings();
  if (!s.contains(QStringLiteral("connection/kind"))) return std::nullopt;
  SessionTarget target;
  target.kind = s.value(QStringLiteral("connection/kind")).toString() == QLatin1String("robot")
                    ? SessionTarget::Kind::kRobot
                    : SessionTarget::Kind::kSimulator;
  xmate::XmateType type = xmate::XMATE7_PRO;
  if (parseModel(s.value(QStringLiteral("connection/model")).toString(), type)) target.type = type;
  QString host;
  quint16 port = 0;
  QString error;
  if (parseHostPort(s.value(QStringLiteral("connection/robot")).toString(), host, port, error)) {
    target.host = host;
    target.port = port;
  }
  return target;
}

void saveLastTarget(const SessionTarget& target) {
  static const char* const kModelKeys[] = {"xmate3_pro", "xmate7_pro", "xmate3", "xmate7"};
  QSettings s = settings();
  s.setValue(QStringLiteral("connection/kind"),
             target.kind == SessionTarget::Kind::kRobot ? QStringLiteral("robot") : QStringLiteral("simulator"));
  s.setValue(QStringLiteral("connection/model"), QString::fromLatin1(kModelKeys[int(target.type)]));
  s.setValue(QStringLiteral("connection/robot"), QStringLiteral("%1:%2").arg(target.host).arg(target.port));
}

std::optional<QString> robotFromIni(const QString& path) {
  if (!QFileInfo::exists(path)) return std::nullopt;
  xmate::INIParser ini;
  if (!ini.ReadINI(path.toStdString())) return std::nullopt;
  const QString ip = QString::fromStdString(ini.GetString("network", "ip")).trimmed();
  const int port = ini.GetInt("network", "port");
  if (ip.isEmpty()) return std::nullopt;
  return QStringLiteral("%1:%2").arg(ip).arg(port > 0 && port <= 65535 ? port : 1337);
}

}  // namespace rci::ui
