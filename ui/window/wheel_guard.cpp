// SPDX-License-Identifier: Apache-2.0
// The scroll-wheel guard (wheel_guard.h): focus policy of the guarded widgets, and wheel events
// over an unfocused one handed to the enclosing scroll areas.
#include "window/wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QScrollBar>
#include <QWheelEvent>

namespace rci::ui {
namespace {

bool isGuardedType(const QWidget* w) {
  if (qobject_cast<const QScrollBar*>(w)) return false;
  return qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QAbstractSlider*>(w) ||
         qobject_cast<const QComboBox*>(w);
}

// Focus by click or Tab only: a wheel turn must not focus the widget (Qt::WheelFocus).
void useStrongFocus(QWidget* w) {
  if (isGuardedType(w) && w->focusPolicy() == Qt::WheelFocus) w->setFocusPolicy(Qt::StrongFocus);
}

bool hasFocusWithin(const QWidget* w) {
  const QWidget* focus = QApplication::focusWidget();
  return w->hasFocus() || (focus && w->isAncestorOf(focus));
}

// Sends a copy of event to each scroll area around w, innermost first, until one scrolls.
void passToScrollAreas(QWidget* w, const QWheelEvent* event) {
  for (QWidget* p = w->parentWidget(); p && !p->isWindow(); p = p->parentWidget()) {
    auto* area = qobject_cast<QAbstractScrollArea*>(p);
    if (!area) continue;
    QWidget* viewport = area->viewport();
    QWheelEvent copy(viewport->mapFromGlobal(event->globalPosition()), event->globalPosition(), event->pixelDelta(),
                     event->angleDelta(), event->buttons(), event->modifiers(), event->phase(), event->inverted(),
                     event->source(), event->pointingDevice());
    copy.setAccepted(false);
    QCoreApplication::sendEvent(viewport, &copy);
    if (copy.isAccepted()) return;
  }
}

}  // namespace

QWidget* wheelGuardedWidget(QWidget* w) {
  for (; w && !w->isWindow(); w = w->parentWidget()) {
    if (isGuardedType(w)) return w;
    if (qobject_cast<QAbstractScrollArea*>(w) || qobject_cast<QScrollBar*>(w)) return nullptr;
  }
  return nullptr;
}

WheelGuard::WheelGuard(QObject* parent) : QObject(parent) { setObjectName(QStringLiteral("wheelGuard")); }

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
  if (event->type() != QEvent::Wheel && event->type() != QEvent::Polish) return false;
  if (!watched->isWidgetType()) return false;
  auto* widget = static_cast<QWidget*>(watched);
  if (event->type() == QEvent::Polish) {
    useStrongFocus(widget);
    return false;
  }
  QWidget* guarded = wheelGuardedWidget(widget);
  if (!guarded || hasFocusWithin(guarded)) return false;
  passToScrollAreas(guarded, static_cast<QWheelEvent*>(event));
  return true;  // the unfocused field keeps its value
}

void installWheelGuard() {
  if (!qApp || qApp->findChild<WheelGuard*>(QString(), Qt::FindDirectChildrenOnly)) return;
  qApp->installEventFilter(new WheelGuard(qApp));
  for (QWidget* w : QApplication::allWidgets()) useStrongFocus(w);
}

}  // namespace rci::ui
