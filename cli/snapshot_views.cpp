// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_views.h"

#include "defect_snapshot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace meshbridge::cli {

namespace {

constexpr double kPi = 3.14159265358979323846;
//! Elevation of the corner views: a little below the exact isometric (35.26 deg), where a box's
//! back corner hides behind its front one and three of its edges are lost.
constexpr double kCornerElevationDegrees = 30;

}  // namespace

ScreenAxes screen_axes(const SnapshotView& view, bool y_up) {
  if (view.automatic || !view.is_valid())
    throw std::invalid_argument("screen_axes: not a drawable view");
  ScreenAxes axes;
  if (view.x != 0 && view.y != 0 && view.z != 0) {
    // Camera at azimuth a (from +x toward +y) and elevation e, +z up on screen.
    const double a = std::atan2(view.y, view.x);
    const double e = view.z * kCornerElevationDegrees * kPi / 180;
    axes = {Point(-std::sin(a), std::cos(a), 0),
            Point(-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e))};
  } else if (view.x != 0) {
    axes = {Point(0, view.x, 0), Point(0, 0, 1)};
  } else if (view.y != 0) {
    axes = {Point(-view.y, 0, 0), Point(0, 0, 1)};
  } else {
    axes = {Point(view.z, 0, 0), Point(0, 1, 0)};
  }
  if (y_up) {
    // Drawn as if the model were turned by R: (x, y, z) -> (x, -z, y), +y to +z; projecting R p
    // on an axis a is projecting p on R^T a = (a.x, a.z, -a.y).
    for (Point* a : {&axes.right, &axes.up})
      *a = Point((*a)[0], (*a)[2], -(*a)[1]);
  }
  return axes;
}

std::vector<SnapshotView> candidate_views() {
  std::vector<SnapshotView> views;
  for (int z : {1, -1}) {
    for (int x : {1, -1}) {
      for (int y : {1, -1})
        views.push_back({false, x, y, z});
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {1, -1})
      views.push_back(SnapshotView::along(axis, sign));
  }
  return views;  // iso = (+1, +1, +1) first
}

ViewChoice choose_view(const Soup& soup, const DefectReport& report,
                       const SnapshotOptions& options) {
  ViewChoice choice;
  if (report.singular_edges.empty() && report.boundary_edges.empty() &&
      report.singular_edge_vertices.empty() && report.pinch_vertices.empty())
    return choice;  // nothing drawn in red or green: every view shows 0
  SnapshotOptions small = options;
  small.size = std::min(options.size, kCandidateSize);
  small.legend = false;
  choice.size = small.size;
  const std::vector<SnapshotView> views = candidate_views();
  const std::vector<std::size_t> counts = detail::count_defect_pixels(soup, report, small, views);
  choice.iso_defect_pixels = counts[0];
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (i == 0 || counts[i] > choice.defect_pixels) {
      choice.view = views[i];
      choice.defect_pixels = counts[i];
    }
  }
  return choice;
}

}  // namespace meshbridge::cli
