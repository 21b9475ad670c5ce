// SPDX-License-Identifier: Apache-2.0
// The --screenshot run: wait until the simulator streams and the 3D view has rendered, save the
// whole window as a PNG, quit with 0 (or 1 and a message on stderr when that was not possible).
#pragma once

#include <QString>

namespace rci::ui {
class MainWindow;
}

// Arms the screenshot on window (already connecting); the application quits when it is done.
void takeScreenshotWhenReady(rci::ui::MainWindow& window, const QString& path);
