// SPDX-License-Identifier: Apache-2.0
// The message strip above the 3D view (banner.h).
#include "window/banner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace rci::ui {

Banner::Banner(QWidget* parent) : QFrame(parent) {
  setObjectName(QStringLiteral("window.banner"));
  setStyleSheet(QStringLiteral("#window\\.banner { background: #fdecea; border: 1px solid #e6a39c; border-radius: 4px; }"
                               "#window\\.banner QLabel { color: #8a1c14; }"));
  label_ = new QLabel(this);
  label_->setObjectName(QStringLiteral("window.banner.text"));
  label_->setWordWrap(true);
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* close = new QToolButton(this);
  close->setObjectName(QStringLiteral("window.banner.close"));
  close->setText(QStringLiteral("✕"));
  close->setAutoRaise(true);
  close->setToolTip(tr("Hide this message"));
  connect(close, &QToolButton::clicked, this, &QWidget::hide);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(10, 6, 6, 6);
  layout->addWidget(label_, 1);
  layout->addWidget(close, 0, Qt::AlignTop);
  hide();
}

void Banner::showError(const QString& text) {
  label_->setText(text);
  show();
}

QString Banner::text() const { return isVisible() ? label_->text() : QString(); }

}  // namespace rci::ui
