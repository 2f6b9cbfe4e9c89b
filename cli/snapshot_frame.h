// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a snapshot's model lands in the image: the view's axes, the centre and the scale, with
// the framing of SnapshotOptions::focus. Part of the meshbridge_pictures module.

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

#include "snapshot_options.h"
#include "snapshot_views.h"
#include "zbuffer_canvas.h"

#include <QRectF>

#include <vector>

namespace meshbridge::cli {

//! What framing a soup needs that does not depend on the view (computed once for all views).
struct Placement {
  std::vector<Index> used;     //!< the vertices of some polygon, each once, ascending
  std::vector<Index> defects;  //!< the vertices of defects (singular, boundary, pinch), each once
  Point centre;                //!< the middle of the used vertices' bounding box
  double unit = 1;             //!< 1 / the largest half-extent of that box from `centre`
};

//! The Placement of `soup` with its defects `report` (report vertices the soup lacks ignored).
Placement place_model(const Soup& soup, const DefectReport& report);

//! Where the model lands in the image: model coordinates are halved, centred on `centre` and
//! scaled by `unit` into [-1, 1] (no overflow even near DBL_MAX), projected on the camera axes,
//! then `mid` goes to the centre of `area` and one unit becomes `scale` pixels.
struct Frame {
  ScreenAxes axes;
  Point forward;  //!< toward the camera: right x up
  Point centre;
  double unit = 1;
  double mid_x = 0, mid_y = 0;
  double scale = 1;
  QRectF area;

  Point normalized(const Point& p) const { return (p * 0.5 - centre * 0.5) * unit; }
  CanvasPoint to_canvas(const Point& p) const {
    const Point n = normalized(p);
    return {area.center().x() + ((n | axes.right) - mid_x) * scale,
            area.center().y() - ((n | axes.up) - mid_y) * scale, n | forward};
  }
};

//! The frame of `soup` (placed as `placement`) seen along `options.view` (not automatic), fitted
//! into `area` as `options.focus` says (see SnapshotFocus).
Frame make_frame(const Soup& soup, const Placement& placement, const SnapshotOptions& options,
                 const QRectF& area);

}  // namespace meshbridge::cli
