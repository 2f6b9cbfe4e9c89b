// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The snapshot's camera directions, and the choice of one (`--view auto`): every candidate view
// drawn small, the one that shows the most defect pixels wins. Part of the meshbridge_pictures
// module (it draws with cli/defect_snapshot.h); no Qt type in this header.

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

#include "snapshot_options.h"

#include <cstddef>
#include <vector>

namespace meshbridge::cli {

//! Screen axes of an orthographic camera in model coordinates: `right` and `up` are orthonormal,
//! and right x up points from the model toward the camera.
struct ScreenAxes {
  Point right;
  Point up;
};

//! The axes of `view` (not automatic; see SnapshotView), turned with the model when `y_up` (the
//! file's +y drawn as +z).
//! \throw std::invalid_argument for an automatic or invalid view
ScreenAxes screen_axes(const SnapshotView& view, bool y_up);

//! The views choose_view tries, in the order ties are broken: iso first, then the other seven
//! corners (+x-y+z, -x+y+z, -x-y+z, then the four below), then +x, -x, +y, -y, +z, -z.
std::vector<SnapshotView> candidate_views();

//! What choose_view found.
struct ViewChoice {
  SnapshotView view = SnapshotView::iso();  //!< the view chosen (never automatic)
  std::size_t defect_pixels = 0;            //!< red + green pixels of `view` at `size`
  std::size_t iso_defect_pixels = 0;        //!< the same for iso
  int size = 0;  //!< the side of the small pictures compared (0: none drawn, no defect)
};

//! The candidate view (candidate_views()) whose picture shows the most defect pixels: red
//! (singular edges and vertices) plus green (boundary edges), where the surface does not hide
//! them, each candidate drawn as `options` say (focus, margin, y_up) but kCandidateSize pixels
//! across at most, without legend, and with dense defects drawn as lines instead of a tint so
//! that they count (a sample of every n-th when there are over 20,000, counted n times: see
//! detail::count_defect_pixels). The first candidate wins a tie, so iso is kept unless another
//! view shows strictly more; a soup without red or green defects gets iso without drawing
//! anything. Deterministic: the same counts whatever the number of threads.
//! \pre as draw_defect_snapshot (validated by the caller)
ViewChoice choose_view(const Soup& soup, const DefectReport& report,
                       const SnapshotOptions& options);

//! The largest side of the pictures choose_view compares (smaller when `options.size` is).
constexpr int kCandidateSize = 200;

}  // namespace meshbridge::cli
