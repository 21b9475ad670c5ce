// SPDX-License-Identifier: Apache-2.0
// The main window's placement and default dock sizes (window_geometry.h).
#include "window/window_geometry.h"

#include <algorithm>

namespace rci::ui {
namespace {

// Room a window manager's frame may take around the client area (title bar, borders).
constexpr int kFrameAllowanceWidth = 16;
constexpr int kFrameAllowanceHeight = 40;

// Side docks: a share of the window width, within [minimum, maximum] pixels.
constexpr double kLeftShare = 0.32;
constexpr int kLeftMin = 400, kLeftMax = 560;
constexpr double kRightShare = 0.26;
constexpr int kRightMin = 360, kRightMax = 400;
// Both side docks together leave at least a third of the width to the 3D view.
constexpr double kSidesMaxShare = 0.66;

constexpr double kPlotsShare = 0.4;
constexpr int kPlotsMin = 200;
constexpr int kSidePanelsMinHeight = 420;  // the side panels' height the plots give way to

// Scales a side dock's width down when both together would take more than kSidesMaxShare.
int fitSides(int width, int window_width) {
  const int both = std::clamp(int(window_width * kLeftShare), kLeftMin, kLeftMax) +
                   std::clamp(int(window_width * kRightShare), kRightMin, kRightMax);
  const double limit = window_width * kSidesMaxShare;
  return both <= limit ? width : int(width * limit / both);
}

}  // namespace

WindowPlacement defaultPlacement(const QRect& available) {
  const QSize with_frame = kPreferredWindowSize + QSize(kFrameAllowanceWidth, kFrameAllowanceHeight);
  if (with_frame.width() <= available.width() && with_frame.height() <= available.height()) {
    QRect centred(QPoint(0, 0), kPreferredWindowSize);
    centred.moveCenter(available.center());
    return {centred, false};
  }
  return {available, true};
}

bool fitsAvailable(const QRect& frame, const QRect& available) { return frame.isValid() && available.contains(frame); }

QString screenSizeGroup(const QSize& available) {
  return QStringLiteral("window/%1x%2").arg(available.width()).arg(available.height());
}

int defaultLeftDockWidth(int window_width) {
  return fitSides(std::clamp(int(window_width * kLeftShare), kLeftMin, kLeftMax), window_width);
}

int defaultRightDockWidth(int window_width) {
  return fitSides(std::clamp(int(window_width * kRightShare), kRightMin, kRightMax), window_width);
}

int defaultPlotsHeight(int window_height, int chrome) {
  const int share = int(window_height * kPlotsShare);
  const int leaving_panels_room = window_height - chrome - kSidePanelsMinHeight;
  return std::max(kPlotsMin, std::min(share, leaving_panels_room));
}

}  // namespace rci::ui
