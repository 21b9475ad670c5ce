// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the tests of tests/gui/ (test_session, test_main_window).
#pragma once

#include <cstdint>

#include <QSettings>
#include <QStandardPaths>
#include <QString>

#include "net/tcp_socket.h"
#include "session/session.h"

namespace rci::ui::test {

// The embedded simulator with the lock-step clock (deterministic on a loaded machine) and the
// DO -> DI loop-back.
inline SessionTarget lockstepSimulator() {
  SessionTarget target;
  target.kind = SessionTarget::Kind::kSimulator;
  target.lockstep = true;
  target.loopback = true;
  return target;
}

// The built-in KUKA simulator (a KR 6 R900 sixx running the sample RSI context, with its F/T sensor).
inline SessionTarget kukaSimulator() {
  SessionTarget target;
  target.kind = SessionTarget::Kind::kKukaSimulator;
  target.kuka_model = QStringLiteral("kr6_r900_sixx");
  return target;
}

// Settings go to a private folder: never the user's, never another test's running in parallel.
// Starts with none saved.
inline void usePrivateSettings(const QString& folder) {
  QStandardPaths::setTestModeEnabled(true);
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder);
  QSettings(QStringLiteral("RCI Studio"), QStringLiteral("rci-studio")).clear();
}

// A TCP port nobody listens on (bound and released again).
inline uint16_t unusedPort() {
  xmate::net::TcpListener listener;
  listener.listen("127.0.0.1", 0);
  const uint16_t port = listener.localPort();
  listener.close();
  return port;
}

}  // namespace rci::ui::test
