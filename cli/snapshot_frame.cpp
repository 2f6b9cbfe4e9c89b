// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_frame.h"

#include <algorithm>
#include <limits>

namespace meshbridge::cli {

Placement place_model(const Soup& soup, const DefectReport& report) {
  Placement placement;
  std::vector<char> mark(soup.num_vertices(), 0);
  for (Index v : soup.corner_vertices)
    mark[v] = 1;
  Point low(std::numeric_limits<double>::max());
  Point high(std::numeric_limits<double>::lowest());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (mark[v]) {
      placement.used.push_back(static_cast<Index>(v));
      low.minimize(soup.positions[v]);
      high.maximize(soup.positions[v]);
    }
  }
  placement.centre = low * 0.5 + high * 0.5;
  double extent = 0;
  for (Index v : placement.used)
    extent = std::max(extent, (soup.positions[v] * 0.5 - placement.centre * 0.5).max_abs());
  placement.unit = extent > 0 ? 1 / extent : 1;

  const auto add = [&](Index v) {
    if (v < mark.size() && mark[v] != 2) {
      mark[v] = 2;
      placement.defects.push_back(v);
    }
  };
  for (const SingularEdge& e : report.singular_edges)
    add(e.vertices.v0), add(e.vertices.v1);
  for (const VertexPair& e : report.boundary_edges)
    add(e.v0), add(e.v1);
  for (Index v : report.pinch_vertices)
    add(v);
  return placement;
}

Frame make_frame(const Soup& soup, const Placement& placement, const SnapshotOptions& options,
                 const QRectF& area) {
  Frame frame;
  frame.axes = screen_axes(options.view, options.y_up);
  frame.forward = frame.axes.right % frame.axes.up;
  frame.area = area;
  frame.centre = placement.centre;
  frame.unit = placement.unit;

  // The projected box of the fitted vertices (the defects' with a focus on them, if any), and of
  // the whole model (a zoom shows at least a tenth of the model's width, so one short defect
  // edge is not blown up to fill the picture).
  const auto box = [&](const std::vector<Index>& which, double* out) {
    out[0] = out[2] = std::numeric_limits<double>::max();
    out[1] = out[3] = std::numeric_limits<double>::lowest();
    for (Index v : which) {
      const Point n = frame.normalized(soup.positions[v]);
      const double x = n | frame.axes.right, y = n | frame.axes.up;
      out[0] = std::min(out[0], x), out[1] = std::max(out[1], x);
      out[2] = std::min(out[2], y), out[3] = std::max(out[3], y);
    }
  };
  double whole[4], fitted[4];
  box(placement.used, whole);
  if (options.focus == SnapshotFocus::whole || placement.defects.empty())
    std::copy(whole, whole + 4, fitted);
  else
    box(placement.defects, fitted);
  const double across = std::max(whole[1] - whole[0], whole[3] - whole[2]);
  SnapshotFocus focus = options.focus;
  if (focus == SnapshotFocus::automatic) {  // defects when small, with the model around them
    const bool small = std::max(fitted[1] - fitted[0], fitted[3] - fitted[2]) < 0.25 * across;
    focus = small ? SnapshotFocus::defects : SnapshotFocus::whole;
    if (!small)
      std::copy(whole, whole + 4, fitted);
  }
  if (focus == SnapshotFocus::defects) {
    const double least = (options.focus == SnapshotFocus::automatic ? 0.4 : 0.1) * across;
    for (int axis = 0; axis < 4; axis += 2) {
      const double middle = (fitted[axis] + fitted[axis + 1]) / 2;
      const double half = std::max((fitted[axis + 1] - fitted[axis]) * 0.55, least / 2);
      fitted[axis] = middle - half, fitted[axis + 1] = middle + half;
    }
  }
  const double width = fitted[1] - fitted[0], height = fitted[3] - fitted[2];
  frame.scale = 1;
  if (width > 1e-12 || height > 1e-12) {
    frame.scale =
        std::min(width > 1e-12 ? area.width() / width : std::numeric_limits<double>::max(),
                 height > 1e-12 ? area.height() / height : std::numeric_limits<double>::max());
  }
  frame.mid_x = (fitted[0] + fitted[1]) / 2;
  frame.mid_y = (fitted[2] + fitted[3]) / 2;
  return frame;
}

}  // namespace meshbridge::cli
