// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file print_preset.h
//! `repair --print`: the slicer route in one option (RepairFileOptions::print). What it sets
//! on the repair, and the repair that takes back removals which would open a surface.

#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include <string>

namespace meshbridge {

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

}  // namespace meshbridge
