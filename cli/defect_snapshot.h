// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A picture of a soup's defects, drawn with Qt into an image (no window, no display). Part of the
// meshbridge_pictures module (cli/pictures_api.h): the CLI's `snapshot` command and `repair
// --before-after` get it as PNG bytes; the core knows nothing of it.

#include "meshbridge/defect_report.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/soup.h"

#include "snapshot_options.h"

#include <QImage>

#include <cstddef>
#include <vector>

namespace meshbridge::cli {

//! What draw_defect_snapshot made.
struct DefectSnapshot {
  QImage image;               //!< size x size, QImage::Format_ARGB32, opaque
  bool legend_drawn = false;  //!< false if the legend was off or text does not render
  //! Pixels within kColorTolerance per channel of the red (220,0,0) / green (0,160,0) the
  //! defects are drawn in, counted in the finished image (the antialiased rims of the lines,
  //! blended with what lies under them, mostly fall outside and are not counted).
  std::size_t red_pixels = 0;
  std::size_t green_pixels = 0;
  //! Pixels of self-intersecting faces: violet (140,0,255) shaded, counted as blue >= 100, green
  //! <= 50, red between 0.3 and 0.8 of blue and at least green + 40 (the rule of MeshLab's GUI
  //! tests, tests/meshlab/count_pixels.cpp).
  std::size_t violet_pixels = 0;
  static constexpr int kColorTolerance = 48;
  //! The view drawn: `options.view`, or the one choose_view chose when that was automatic.
  SnapshotView view = SnapshotView::iso();
};

//! True for a pixel counted in DefectSnapshot::violet_pixels.
bool is_violet(unsigned red, unsigned green, unsigned blue);

//! Draws `soup` seen orthographically along `options.view`. When that is automatic: along the
//! view choose_view() in cli/snapshot_views.h picks for `frame_soup` if given; else for `soup`,
//! if drawn at full size it shows more defect pixels than iso, else iso (so the automatic view
//! never shows fewer defect pixels than iso; the ranking counts red and green, not violet). Its
//! polygons flat-shaded light grey (Lambert, one fixed light, both sides lit) with a depth buffer,
//! on white; on top, where the surface does not hide them, boundary edges green (0,160,0), 2 px,
//! and singular edges red (220,0,0), 3 px, with singular vertices (singular-edge endpoints and
//! pinch vertices) as red dots 7 px across; the faces of `crossings` (when given: self-intersecting
//! faces) are shaded violet (140,0,255) instead of grey, the colour MeshLab's Detect shows them in;
//! widths grow with `size` above 800 and shrink (to 1 px) where the defect edges are short on
//! screen, so a dense mesh shows a grid rather than a solid colour. Defect edges behind the surface
//! are drawn 1 px in pale red / pale green (not counted). Polygons smaller than a pixel still
//! colour the pixel under their centre. The model (or with SnapshotFocus::defects the defects'
//! bounding box) is fitted into the image inside the margin, below the legend; with `frame_soup`
//! the fit is that of `frame_soup` and `frame_report` instead, so two pictures (before and after a
//! repair) line up. The legend is one black line, "TITLE: N singular edges, M singular vertices, K
//! boundary edges" (with `crossings` followed by ", F self-intersecting faces"); text needs a
//! QGuiApplication (the CLI makes one on the "offscreen" platform), so without one the legend is
//! left out and the rest is drawn all the same.
//! \pre `soup` passes validate_soup(); `report` is detect_defects(soup); `crossings` null or
//! find_self_intersections(soup); `options.size` in [kMinSize, kMaxSize]; `options.margin` in
//! [0, 0.45]; `frame_report` set when `frame_soup` is
//! \throw InvalidSoupError from validate_soup()
//! \throw std::invalid_argument naming the bad option, or a report vertex or face the soup lacks
DefectSnapshot draw_defect_snapshot(const Soup& soup, const DefectReport& report,
                                    const SnapshotOptions& options = {},
                                    const Soup* frame_soup = nullptr,
                                    const DefectReport* frame_report = nullptr,
                                    const SelfIntersectionReport* crossings = nullptr);

namespace detail {
//! For choose_view: the red + green pixels of `soup` drawn along each of `views` (not automatic)
//! as draw_defect_snapshot draws it with `options`, but without legend, without shading, with
//! dense defects as opaque lines (not a tint) and no hidden defect lines; of more than 20,000
//! edges or dots of one colour, every n-th is drawn and its pixels count n times. The framing
//! is computed once for all views, and a view and its opposite are drawn in one pass.
//! \pre as draw_defect_snapshot (not checked here)
std::vector<std::size_t> count_defect_pixels(const Soup& soup, const DefectReport& report,
                                             const SnapshotOptions& options,
                                             const std::vector<SnapshotView>& views);
}  // namespace detail

//! `left` and `right` side by side with a 2-pixel grey rule between them (heights may differ;
//! the rest is white). Pixel counts add up; the view is the left one's.
DefectSnapshot side_by_side(const DefectSnapshot& left, const DefectSnapshot& right);

}  // namespace meshbridge::cli
