// SPDX-License-Identifier: Apache-2.0
// Operator text for the pre-flight problems of a program (operator_text.h): the checker's sentences
// are plain already; the window drops the solver's codes and says which button does the re-teach.
#include <QCoreApplication>
#include <QRegularExpression>

#include "text/operator_text.h"

namespace rci::ui::text {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("OperatorText", text); }

}  // namespace

QString programProblem(const std::string& raw) {
  QString plain = QString::fromStdString(raw).trimmed();
  static const QRegularExpression code(QStringLiteral(R"( \(IK code -?\d+\))"));
  plain.remove(code);
  plain.replace(QStringLiteral("re-teach it, or give the target's joint angles \"q\""),
                tr("re-teach it (Touch up in the Program panel)"));
  plain.replace(QStringLiteral("re-teach the target or reach it with MOVEJ"),
                tr("re-teach the target (Touch up) or make it a joint move (type J)"));
  plain.replace(QStringLiteral("re-teach the waypoint"), tr("re-teach the waypoint (Touch up)"));
  plain.replace(QStringLiteral("set the tool and load the program was taught with, or teach the program again with this tool"),
                tr("enter that tool in the Tool & payload panel and press Apply, or press New in the Program "
                   "panel and teach the program again with this tool"));
  return plain;
}

}  // namespace rci::ui::text
