// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file close_gaps.h
//! Closing rounding-level cracks before pairing: welding near vertices and splitting boundary
//! sides at T-junctions (DESIGN 8a, "Gaps").

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <vector>

namespace meshbridge {

//! Marks "choose the weld tolerance from the coordinates" (see default_weld_tolerance()).
inline constexpr double kAutoWeldTolerance = -1.0;

//! What gap closing may do. Defaults: on, with the automatic tolerance.
struct CloseGapsOptions {
  //! Distance (in the soup's length unit) below which two vertices are one. kAutoWeldTolerance
  //! (default, any negative value) uses default_weld_tolerance(); 0 turns gap closing off (both
  //! welding and T-junction splitting). Must not be NaN or infinite.
  double tolerance = kAutoWeldTolerance;
  //! Also split a boundary side where another boundary vertex lies on it within the tolerance
  //! (T-junction crack). Default on.
  bool close_t_junctions = true;
};

//! What gap closing did. Every count is exact.
struct CloseGapsReport {
  double tolerance = 0;                //!< the tolerance used (0: gap closing was off)
  std::size_t vertices_welded = 0;     //!< vertices merged into another (removed from the soup)
  double largest_weld_distance = 0;    //!< largest distance a welded vertex moved
  std::size_t welds_refused = 0;       //!< near pairs not welded: they share a polygon
  std::size_t t_junctions_closed = 0;  //!< boundary vertices inserted into a boundary side
  std::size_t sides_split = 0;         //!< boundary sides split by those insertions
  //! True when the soup changed (a weld or a split happened).
  bool changed() const { return vertices_welded != 0 || t_junctions_closed != 0; }
};

//! The soup with its gaps closed, and where every element came from.
//!
//! Faces keep their number and order (a T-junction split adds a corner to a polygon, never a
//! polygon). Welded vertices disappear; the survivors keep their relative order.
struct ClosedGaps {
  Soup soup;                         //!< the soup after welding and splitting
  std::vector<Index> vertex_origin;  //!< #V': input vertex of each vertex (the weld's survivor)
  //! #C': input corner of each corner. A corner inserted by a T-junction split takes the corner
  //! that starts the split side, so per-corner attributes (wedge texture coordinates) are
  //! copied from its neighbour.
  std::vector<Index> corner_origin;
  CloseGapsReport report;
};

//! The automatic tolerance: 2^-21 (about 4.8e-7) times the largest absolute coordinate of a
//! vertex some face uses (an isolated vertex takes no part in welding), that is
//! 4 to 8 units in the last place of a float32 (STL) coordinate at that magnitude — the size of
//! the rounding differences that CAD exports leave between copies of one vertex, and far below
//! any feature a printer can make (7.2e-5 mm at 150 mm). 0 for an empty soup or one at the
//! origin.
double default_weld_tolerance(const Soup& soup);

//! Welds boundary vertices (ends of edges with one side) closer than the tolerance, then (if
//! enabled) splits every boundary side on which another boundary vertex lies within the tolerance.
//!
//! Only boundary vertices weld: a crack is where sides are open, so a closed mesh, however near
//! its vertices, is left exactly as it is. Vertices at exactly the same position are never welded:
//! a file that lists a position twice (an OBJ seam, a repaired mesh's split vertex copies) keeps
//! them apart on purpose, and STL readers already merged identical positions; so repairing a
//! repaired mesh changes nothing. Welding visits vertices in index order; each one merges into the
//! nearest earlier surviving vertex within the tolerance that shares no polygon with it (so no
//! polygon loses a corner; such refusals are counted), and takes its position. Near-linear: a hash
//! grid of cell size 4x the tolerance. A gap wider than the tolerance stays open (its sides stay
//! boundary). \pre `soup` passes validate_soup(); `options.tolerance` is finite or negative \throw
//! std::invalid_argument if `options.tolerance` is NaN or +infinite
ClosedGaps close_gaps(const Soup& soup, const CloseGapsOptions& options = {});

//! What close_gaps(soup, options) would do: its report, without the copy of the soup (and the
//! identity origins) that close_gaps() returns when nothing changes. A closed mesh, which has no
//! boundary vertex, costs one pass over the corners; none when `detected` (optional) is
//! detect_defects(soup) and lists no boundary edge and no degenerate face. `meshbridge check`
//! prints it. \pre as close_gaps(); `detected`, when given, is detect_defects(soup)
//! \throw as close_gaps()
CloseGapsReport preview_close_gaps(const Soup& soup, const CloseGapsOptions& options = {},
                                   const DefectReport* detected = nullptr);

}  // namespace meshbridge
