// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `repair --print`: the slicer route in one option. What it sets, and the paragraph that says
// what is still open in the printed file and why.

#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include <string>

namespace meshbridge::cli {

//! The gap closing distance of `--print` when `--weld` is not given: 1e-4 times the diagonal
//! of the soup's bounding box, the widest nearby-edge tolerance of PrusaSlicer's load-time
//! repair (admesh's stl_check_facets_nearby: the shortest edge, then that plus the diagonal /
//! 10000), never less than the automatic tolerance's largest per-vertex value. 0 for an empty
//! soup.
double print_weld_tolerance(const Soup& soup);

//! What `--print` sets on `options` for the soup read (`weld_given`, `fill_holes_given`: the
//! user's own --weld and --fill-holes win): gap closing at print_weld_tolerance(), duplicate
//! faces (same vertex set) and faces of zero area removed (repair_for_print() keeps them where
//! that opens a surface),
//! holes of up to kDefaultFillHolesMaxEdges (32) edges filled. Faces of fewer than 3 distinct
//! corners (admesh's "degenerate facets") are set aside by every repair; a polygon that merely
//! repeats a vertex (pinched) is split into simple ones, not removed.
void apply_print_preset(const Soup& soup, bool weld_given, bool fill_holes_given,
                        RepairOptions& options);

//! repair(soup, options) for `--print`. Removing duplicate faces can open a surface: a sheet
//! written twice, back to back (each triangle once per winding), which a slicer reads as closed
//! parts of no volume; so can removing a sliver of zero area that closes a crack. When the repair
//! with a removal leaves more open edges than the input had, it runs again without it (the
//! duplicates first, then the zero-area faces), and `note` says so (empty otherwise).
RepairResult repair_for_print(const Soup& soup, RepairOptions options, std::string& note);

//! The `print:` paragraph of the summary: whether the written mesh is watertight, and for each
//! open edge left the reason (holes longer than the filling's limit, outlines of open sheets,
//! boundaries of odd singular edges, gap closing refused) with the option that would change it.
//! `written` (may be null): detection on the file as written when that differs from the repaired
//! polygons (an STL re-read, a 3MF's triangles).
std::string print_summary(const RepairReport& report, const DefectReport* written = nullptr);

//! For a repair without --print that leaves open edges: one `hint:` line naming them and what
//! would close them (--fill-holes when filling was off, --print); "" when the result is closed.
std::string open_edges_hint(const RepairReport& report);

}  // namespace meshbridge::cli
