// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The printer-route options shared by check, repair and batch: --weld, --separate, and what an
// STL file re-reads as.

#include "meshbridge/close_gaps.h"
#include "meshbridge/defect_report.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/pairing.h"
#include "meshbridge/repair_file.h"
#include "meshbridge/stl_round_trip.h"

#include <CLI/CLI.hpp>

#include <cstddef>
#include <iosfwd>
#include <string>

namespace meshbridge::cli {

//! `--weld TOL`: "auto" (the default) or a distance >= 0 (0 = off). Throws UsageError otherwise.
CloseGapsOptions parse_weld(const std::string& text);

//! `--separate EPS`: "auto" (the default) is kAutoSeparation, else a distance >= 0 (0 = positions
//! exact). Throws UsageError otherwise.
double parse_separation(const std::string& text);

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

//! The summary line of `--separate TEXT` (`given`: on the command line) after repair_file()
//! moved `separated` of a mesh with `vertices_split` copies written to `out`: what moved and how
//! far, why copies kept their positions, or, when `given` for a format that keeps shared
//! vertices, that nothing was needed; "" otherwise.
std::string separation_summary(const StlSeparation& separated, std::size_t vertices_split,
                               const std::string& text, bool given, const std::string& out);

}  // namespace meshbridge::cli
