// SPDX-License-Identifier: Apache-2.0
// Target persistence and parsing for the connection bar (target_settings.h).
#include "window/target_settings.h"

#include <QFileInfo>
#include <QSettings>

#include <xmate/ini.h>

#include "net/host_port.h"

namespace rci::ui {
namespace {

constexpr int kMaxRecent = 8;

QSettings settings() { return QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")); }

}  // namespace

bool parseHostPort(const QString& text, QString& host, quint16& port, QString& error) {
  const QString trimmed = text.trimmed();
  xmate::net::HostPort split;
  const xmate::net::HostPortProblem problem = xmate::net::splitHostPort(trimmed.toStdString(), 0, split);
  if (problem == xmate::net::HostPortProblem::kNoHost || problem == xmate::net::HostPortProblem::kNoPort ||
      (problem == xmate::net::HostPortProblem::kBadPort && split.port_text.empty())) {
    error = QStringLiteral("\"%1\" is not a robot address. Enter it as HOST:PORT, e.g. 192.168.0.160:1337.")
                .arg(trimmed);
    return false;
  }
  if (problem == xmate::net::HostPortProblem::kBadPort) {
    error = QStringLiteral("\"%1\" is not a port. Use a number from 1 to 65535 (the RCI default is 1337).")
                .arg(QString::fromStdString(split.port_text));
    return false;
  }
  const QString name = QString::fromStdString(split.host);
  if (name.contains(QLatin1Char(' '))) {
    error = QStringLiteral("\"%1\" is not a host name or IP address (it contains a space).").arg(name);
    return false;
  }
  host = name;
  port = split.port;
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
