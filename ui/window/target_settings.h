// SPDX-License-Identifier: Apache-2.0
// Where the window connects: parsing "HOST:PORT", the recent robots and the last target (QSettings),
// and the robot address from an xmate.ini in the working directory.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>

#include "session/session.h"

namespace rci::ui {

// Parses "HOST:PORT" (port 1..65535). On failure returns false and sets error to a sentence that
// says what was wrong and what to enter.
bool parseHostPort(const QString& text, QString& host, quint16& port, QString& error);

// Robots connected to before, newest first ("192.168.0.160:1337"), at most 8.
QStringList recentRobots();
void rememberRobot(const QString& host_port);

// The last target connected to (none saved yet: nullopt).
std::optional<SessionTarget> lastTarget();
void saveLastTarget(const SessionTarget& target);

// "HOST:PORT" from [network] ip / port of the xmate.ini in the working directory; nullopt when
// there is none or it does not name an address.
std::optional<QString> robotFromIni(const QString& path = QStringLiteral("xmate.ini"));

}  // namespace rci::ui
