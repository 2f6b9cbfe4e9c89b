// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer-route options shared by check, repair and batch: --weld, --separate, and what an
// STL file re-reads as.

#include "meshbridge/close_gaps.h"
#include "meshbridge/defect_report.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/pairing.h"
#include "meshbridge/stl_round_trip.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <iosfwd>
#include <string>

namespace meshbridge::cli {

//! `--weld TOL`: "auto" (the default) or a distance >= 0 (0 = off). Throws UsageError otherwise.
CloseGapsOptions parse_weld(const std::string& text);

//! Adds `--fill-holes [MAX_EDGES]` to `command` (repair and batch), storing its text into
//! `max_edges`: given without a number it is kDefaultFillHolesMaxEdges (32); absent it stays
//! as it was (empty: off). Read it with parse_fill_holes().
void add_fill_holes_option(CLI::App& command, std::string& max_edges);

//! Adds `--nested-shells material|cavity` to `command` (check, repair): what a closed shell
//! wound like the closed shell around it becomes (RepairOptions::nested_shells).
void add_nested_shells_option(CLI::App& command, AmbiguousNesting& nested);

//! The `max_edges` of FillHolesOptions from add_fill_holes_option's text (empty or "0": off).
std::size_t parse_fill_holes(const std::string& text);

//! One line describing what gap closing did (or would do, for check).
std::string gaps_line(const CloseGapsReport& report, bool would);

//! For check with the automatic tolerance: cracks wider than it stay open, so when `detected`
//! has boundary edges, what 100 times that tolerance (rounded up to one digit) would weld and
//! close, as a line "hint: --weld 5e-05 would weld 12 vertices ... (N now)", or "" when it would
//! close nothing more than `gaps` (the preview at the automatic tolerance).
std::string wider_weld_hint(const Soup& soup, const CloseGapsOptions& weld,
                            const CloseGapsReport& gaps, const DefectReport& detected);

//! True if `path` ends with ".stl" (any case).
bool is_stl_path(const std::string& path);

//! `--separate auto|EPS` applied to a repaired mesh about to be written to `out`: for STL, auto
//! (the default) is separate_copies_for_stl() and 0 keeps positions exact; an explicit EPS that
//! float32 cannot hold is a UsageError naming the smallest EPS that works. Other formats keep
//! shared vertices: nothing moves (an explicit EPS still moves the copies). Prints one summary
//! line when anything moved, when copies could not be moved, or when `given` for another format.
StlSeparation apply_separate(const std::string& text, bool given, IndexedMesh& mesh,
                             std::size_t vertices_split, const std::string& out,
                             std::ostream& summary);

//! Detection on the file at `path` as a reader gets it back (read_soup, no repair).
DefectReport detect_as_reread(const std::string& path);

}  // namespace meshbridge::cli
