// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file close_gaps.h
//! Closing rounding-level cracks before pairing: welding near vertices and splitting boundary
//! sides at T-junctions (DESIGN 8a, "Gaps").

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <string>
#include <vector>

namespace meshbridge {

//! Marks "choose the weld tolerance from the coordinates" (see default_weld_tolerance()).
inline constexpr double kAutoWeldTolerance = -1.0;

//! What gap closing may do. Defaults: on, with the automatic tolerance.
struct CloseGapsOptions {
  //! Distance (in the soup's length unit) below which two vertices are one. kAutoWeldTolerance
  //! (default, any negative value) gives each vertex its own tolerance (see
  //! default_weld_tolerance()); 0 turns gap closing off (both welding and T-junction splitting).
  //! Must not be NaN or infinite.
  double tolerance = kAutoWeldTolerance;
  //! The coordinates were stored as 32-bit floats (binary or ASCII STL, 3MF, PLY `float`, a
  //! MeshLab layer): the automatic tolerance of a vertex is then at least 2^-21 times its largest
  //! coordinate, what float32 itself rounds there. Default false: doubles, as the soup holds
  //! them (OBJ, OFF, PLY `double`, numpy float64), where only the part's own extent counts.
  bool float_coordinates = false;
  //! Also split a boundary side where another boundary vertex lies on it within the tolerance
  //! (T-junction crack). Default on.
  bool close_t_junctions = true;
};

//! What gap closing did. Every count is exact.
struct CloseGapsReport {
  double tolerance = 0;              //!< the tolerance used (0: gap closing was off)
  std::size_t vertices_welded = 0;   //!< vertices merged into another (removed from the soup)
  double largest_weld_distance = 0;  //!< largest distance a welded vertex moved
  //! True when the tolerance was automatic (per vertex; `tolerance` is then the largest one of a
  //! boundary vertex, 0 when the soup has no boundary edge).
  bool automatic = false;
  std::size_t welds_refused = 0;  //!< near pairs not welded: they share a polygon
  //! Near pairs not welded because the weld would move a vertex by more than a quarter of the
  //! shortest edge at either of them (a feature of the model, not a crack).
  std::size_t welds_too_long = 0;
  //! Boundary vertices within the tolerance of a boundary side but not put into it: farther from
  //! it than a quarter of that side or of the shortest edge at the vertex.
  std::size_t t_junctions_too_wide = 0;
  std::size_t t_junctions_closed = 0;  //!< boundary vertices inserted into a boundary side
  std::size_t sides_split = 0;         //!< boundary sides split by those insertions
  //! Welds and T-junction closings that repair found and then refused, because the repaired
  //! mesh would have been worse with them than without (DESIGN 8a, no new defects): more open
  //! edges, or more non-orientable components. The counts above are then 0, and `refused_reason`
  //! says what they would have done. 0 and empty otherwise, and in preview_close_gaps().
  std::size_t welds_undone = 0;
  std::size_t t_junctions_undone = 0;
  std::string refused_reason;
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

//! The largest automatic tolerance of a vertex some face uses (DESIGN 8a, gaps). Each vertex
//! has its own: 2^-21 (about 4.8e-7) times the extent of its connected component (the largest
//! side of that component's bounding box) — the size of the rounding differences that CAD
//! exports leave between copies of one vertex, relative to the part, and far below any feature
//! a printer can make (7.2e-5 mm for a 150 mm part) — and, with `float_coordinates`, at least
//! 2^-21 times its own largest absolute coordinate (4 to 8 float32 units in the last place
//! there). Two vertices weld within the smaller of their tolerances. So neither a model's
//! distance from the origin (UTM coordinates held as doubles) nor a far stray facet widens the
//! tolerance of anything else. 0 for an empty soup or one whose parts have no extent.
double default_weld_tolerance(const Soup& soup, bool float_coordinates = false);

//! Welds boundary vertices (ends of edges with one side) closer than the tolerance, then (if
//! enabled) splits every boundary side on which another boundary vertex lies within the tolerance.
//! No weld moves a vertex, and no T-junction closing bridges a gap, longer than a quarter of the
//! shortest non-zero edge at either vertex (or of the split side): such pairs are counted
//! (`welds_too_long`, `t_junctions_too_wide`) and left apart, whatever the tolerance.
//!
//! Only boundary vertices weld: a crack is where sides are open, so a closed mesh, however near
//! its vertices, is left exactly as it is. Vertices at exactly the same position are never welded:
//! a file that lists a position twice (an OBJ seam, a repaired mesh's split vertex copies) keeps
//! them apart on purpose, and STL readers already merged identical positions; so repairing a
//! repaired mesh changes nothing. Welding visits vertices in index order; each one merges into the
//! nearest earlier surviving vertex within the tolerance that shares no polygon with it (so no
//! polygon loses a corner; such refusals are counted), and takes its position. O(n log n): a
//! kd-tree over the boundary vertices. A gap wider than the tolerance stays open (its sides stay
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
