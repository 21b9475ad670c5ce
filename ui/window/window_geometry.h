// SPDX-License-Identifier: Apache-2.0
// Where and how large the main window opens on a screen, and the default sizes of its docks for a
// window size: plain functions of sizes, so the rules can be read (and tested) in one place.
#pragma once

#include <QRect>
#include <QSize>
#include <QString>

namespace rci::ui {

// The size the window prefers; it opens at this size where the screen has room for it.
inline constexpr QSize kPreferredWindowSize{1600, 1000};

struct WindowPlacement {
  QRect geometry;          // the window's client geometry (without the frame)
  bool maximized = false;  // the screen is smaller than the preferred size: open maximized
};

// The default placement on a screen whose available area is available: the preferred size,
// centred, when it fits with room for a title bar; otherwise the whole available area, maximized.
WindowPlacement defaultPlacement(const QRect& available);

// True when frame (the window with its frame) lies within the available area.
bool fitsAvailable(const QRect& frame, const QRect& available);

// The settings group that holds the window's geometry for screens of this available size.
QString screenSizeGroup(const QSize& available);

// Default widths of the left and right side docks (their panels, without the vertical tab bar)
// for a window this wide: the panels' room, narrower on small screens so the 3D view keeps a third.
int defaultLeftDockWidth(int window_width);
int defaultRightDockWidth(int window_width);
// Default height of the bottom dock (plots) for a window this high whose menu, tool and status bars
// take chrome pixels: 40 %, less where the side panels would get less than their minimum height.
int defaultPlotsHeight(int window_height, int chrome);

}  // namespace rci::ui
