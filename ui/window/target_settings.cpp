// SPDX-License-Identifier: Apache-2.0
// Target persistence and parsing for the connection bar (target_settings.h).
#include "window/target_settings.h"

#include <QFileInfo>
#include <QSettings>

#include <exception>

#include <xmate/ini.h>

#include "model/robot_spec.h"
#include "net/host_port.h"
#include "rsi/config.h"

namespace rci::ui {
namespace {

constexpr int kMaxRecent = 8;

QSettings settings() { return QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")); }

QString qt(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

// Puts item first in the list under key, at most kMaxRecent entries.
void rememberIn(const QString& key, const QString& item) {
  QSettings s = settings();
  QStringList list = s.value(key).toStringList();
  list.removeAll(item);
  list.prepend(item);
  while (list.size() > kMaxRecent) list.removeLast();
  s.setValue(key, list);
}

// The saved words for the kinds (the first two as written before the KUKA kinds came).
const char* kindKey(SessionTarget::Kind kind) {
  switch (kind) {
    case SessionTarget::Kind::kSimulator: return "simulator";
    case SessionTarget::Kind::kRobot: return "robot";
    case SessionTarget::Kind::kKukaSimulator: return "kuka_simulator";
    case SessionTarget::Kind::kKukaRobot: return "kuka_rsi";
  }
  return "simulator";
}

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

bool parseSensorAddress(const QString& text, QString& address, QString& error) {
  const QString trimmed = text.trimmed();
  if (trimmed.isEmpty()) {
    address.clear();
    return true;
  }
  xmate::net::HostPort split;
  const xmate::net::HostPortProblem problem = xmate::net::splitHostPort(trimmed.toStdString(), 49152, split);
  const QString name = QString::fromStdString(split.host);
  if (problem == xmate::net::HostPortProblem::kNoHost || name.contains(QLatin1Char(' '))) {
    error = QStringLiteral("\"%1\" is not an F/T sensor address. Enter it as HOST or HOST:PORT, e.g. 192.168.1.1 "
                           "(the sensor's RDT port 49152 is the default), or leave the field empty for no sensor.")
                .arg(trimmed);
    return false;
  }
  if (problem != xmate::net::HostPortProblem::kNone) {
    error = QStringLiteral("\"%1\" is not a port of the F/T sensor \"%2\". Use a number from 1 to 65535 (RDT: "
                           "49152), or give the address without a port.")
                .arg(QString::fromStdString(split.port_text), trimmed);
    return false;
  }
  address = trimmed;
  return true;
}

bool parseKukaModel(const QString& text, QString& name) {
  const xmate::model::RobotSpec* spec = xmate::model::findRobotSpec(text.trimmed().toLower().toStdString());
  if (spec == nullptr || spec->family != xmate::model::RobotFamily::kKuka) return false;
  name = qt(spec->name);
  return true;
}

bool parseAnyModel(const QString& text, xmate::XmateType& type, QString& kuka_name, bool& kuka) {
  if (parseModel(text, type)) {
    kuka = false;
    return true;
  }
  if (parseKukaModel(text, kuka_name)) {
    kuka = true;
    return true;
  }
  return false;
}

bool rsiListenAddress(const QString& path, QString& listen, QString& error) {
  const QString file = path.trimmed();
  if (file.isEmpty()) {
    error = QStringLiteral("No RSI Ethernet config chosen. Choose the robot's Ethernet config file (e.g. "
                           "RSI_EthernetConfig.xml, copied from the controller) with the … button.");
    return false;
  }
  const QFileInfo info(file);
  if (!info.exists() || !info.isFile()) {
    error = QStringLiteral("The RSI Ethernet config \"%1\" does not exist. Choose the robot's Ethernet config file "
                           "(e.g. RSI_EthernetConfig.xml, copied from the controller).")
                .arg(file);
    return false;
  }
  try {
    const xmate::rsi::EthernetConfig config = xmate::rsi::readEthernetConfig(file.toStdString());
    listen = config.ip_is_placeholder
                 ? QStringLiteral("port %1 (all addresses)").arg(config.port)
                 : QStringLiteral("%1:%2").arg(QString::fromStdString(config.ip)).arg(config.port);
    return true;
  } catch (const std::exception& e) {
    QString what = QString::fromStdString(e.what()).trimmed();
    if (!what.endsWith(QLatin1Char('.')) && !what.endsWith(QLatin1Char('?')) && !what.endsWith(QLatin1Char('!')))
      what += QLatin1Char('.');
    error = QStringLiteral("The RSI Ethernet config cannot be used: %1 Correct the file (it must be the one the "
                           "robot's RSI context names) or choose another.")
                .arg(what);
    return false;
  }
}

QStringList recentRobots() { return settings().value(QStringLiteral("connection/recent")).toStringList(); }

void rememberRobot(const QString& host_port) { rememberIn(QStringLiteral("connection/recent"), host_port); }

QStringList recentRsiConfigs() { return settings().value(QStringLiteral("connection/recent_rsi")).toStringList(); }

void rememberRsiConfig(const QString& path) { rememberIn(QStringLiteral("connection/recent_rsi"), path); }

std::optional<SessionTarget> lastTarget() {
  QSettings s = settings();
  if (!s.contains(QStringLiteral("connection/kind"))) return std::nullopt;
  SessionTarget target;
  const QString kind = s.value(QStringLiteral("connection/kind")).toString();
  target.kind = SessionTarget::Kind::kSimulator;
  for (SessionTarget::Kind k : {SessionTarget::Kind::kRobot, SessionTarget::Kind::kKukaSimulator,
                                SessionTarget::Kind::kKukaRobot})
    if (kind == QLatin1String(kindKey(k))) target.kind = k;
  xmate::XmateType type = xmate::XMATE7_PRO;
  if (parseModel(s.value(QStringLiteral("connection/model")).toString(), type)) target.type = type;
  QString host;
  quint16 port = 0;
  QString error;
  if (parseHostPort(s.value(QStringLiteral("connection/robot")).toString(), host, port, error)) {
    target.host = host;
    target.port = port;
  }
  QString kuka_model;
  if (parseKukaModel(s.value(QStringLiteral("connection/kuka_model")).toString(), kuka_model))
    target.kuka_model = kuka_model;
  target.rsi_config = s.value(QStringLiteral("connection/rsi_config")).toString();
  QString sensor;
  if (parseSensorAddress(s.value(QStringLiteral("connection/ft_sensor")).toString(), sensor, error))
    target.ft_sensor = sensor;
  // A KUKA robot without its Ethernet config cannot be connected to: show the simulator instead.
  if (target.kind == SessionTarget::Kind::kKukaRobot && target.rsi_config.isEmpty())
    target.kind = SessionTarget::Kind::kKukaSimulator;
  // The robot's context only with the robot (the simulator would run it instead of its sample).
  if (target.kind == SessionTarget::Kind::kKukaRobot)
    target.rsi_context = s.value(QStringLiteral("connection/rsi_context")).toString();
  return target;
}

void saveLastTarget(const SessionTarget& target) {
  QSettings s = settings();
  s.setValue(QStringLiteral("connection/kind"), QString::fromLatin1(kindKey(target.kind)));
  if (!target.isKuka()) {
    s.setValue(QStringLiteral("connection/model"), qt(xmate::model::robotSpec(target.type).name));
    s.setValue(QStringLiteral("connection/robot"), QStringLiteral("%1:%2").arg(target.host).arg(target.port));
    return;
  }
  QString kuka_model;
  if (parseKukaModel(target.kuka_model, kuka_model)) s.setValue(QStringLiteral("connection/kuka_model"), kuka_model);
  if (target.kind == SessionTarget::Kind::kKukaRobot) {
    s.setValue(QStringLiteral("connection/rsi_config"), target.rsi_config);
    s.setValue(QStringLiteral("connection/ft_sensor"), target.ft_sensor);
    s.setValue(QStringLiteral("connection/rsi_context"), target.rsi_context);
    if (!target.rsi_config.isEmpty()) rememberRsiConfig(target.rsi_config);
  }
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
