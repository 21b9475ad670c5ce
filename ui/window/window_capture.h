// SPDX-License-Identifier: Apache-2.0
// Renders the whole main window to an image, with the 3D view's own capture painted over its
// place (QWidget::grab() does not capture Qt3D).
#pragma once

#include <QImage>

#include <functional>

namespace rci::ui {

class MainWindow;

// Calls done on the GUI thread with the composed image; scene_captured says whether the 3D view
// delivered its picture (false: the grab shows its placeholder).
void captureWindow(MainWindow& window, std::function<void(const QImage& image, bool scene_captured)> done);

// Writes image as PNG atomically (QSaveFile). false and error set on failure.
bool savePng(const QImage& image, const QString& path, QString& error);

}  // namespace rci::ui
