// SPDX-License-Identifier: Apache-2.0
// Where the window connects: parsing "HOST:PORT", an F/T sensor's address, a KUKA model and an RSI
// Ethernet config; the recent robots and RSI configs and the last target (QSettings); and the robot
// address from an xmate.ini in the working directory. GUI thread (QSettings), parsing: any thread.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>

#include "session/session.h"

namespace rci::ui {

// Parses "HOST:PORT" (port 1..65535). On failure returns false and sets error to a sentence that
// says what was wrong and what to enter.
bool parseHostPort(const QString& text, QString& host, quint16& port, QString& error);

// Parses an F/T sensor's address "HOST" or "HOST:PORT" (port 1..65535; without one the sensor's
// RDT port 49152). "" is accepted: no sensor. address gets the trimmed text. false and error set
// (what was wrong, what to enter) otherwise. Any thread.
bool parseSensorAddress(const QString& text, QString& address, QString& error);

// True if text names a KUKA model ("kr6_r900_sixx", "kr16_2"; any case); name gets the file stem.
bool parseKukaModel(const QString& text, QString& name);
// The same for any model of either family: kuka is set to which family it is.
bool parseAnyModel(const QString& text, xmate::XmateType& type, QString& kuka_name, bool& kuka);

// Reads the RSI Ethernet config at path and says where this PC listens for the robot:
// "192.168.1.20:49152", or "port 49152 (all addresses)" when IP_NUMBER is not an address. false and
// error set (the file, what is wrong in it, what to do) when the file is missing or unreadable.
// Any thread; reads the file.
bool rsiListenAddress(const QString& path, QString& listen, QString& error);

// Robots connected to before, newest first ("192.168.0.160:1337"), at most 8.
QStringList recentRobots();
void rememberRobot(const QString& host_port);
// RSI Ethernet configs (absolute paths) connected with before, newest first, at most 8.
QStringList recentRsiConfigs();
void rememberRsiConfig(const QString& path);

// The last target connected to (none saved yet: nullopt). Saved xMate targets from before the KUKA
// kinds read as they did. A KUKA target keeps the Ethernet config and sensor last used with a robot
// (and, for a KUKA robot, its RSI context).
std::optional<SessionTarget> lastTarget();
// Saves target as the last one. The xMate model, robot address, KUKA model, Ethernet config and
// sensor are saved only from targets that have them, so switching kinds keeps the others. Saving a
// KUKA robot also remembers its Ethernet config (recentRsiConfigs).
void saveLastTarget(const SessionTarget& target);

// "HOST:PORT" from [network] ip / port of the xmate.ini in the working directory; nullopt when
// there is none or it does not name an address.
std::optional<QString> robotFromIni(const QString& path = QStringLiteral("xmate.ini"));

}  // namespace rci::ui
