// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/print_preset.h"

#include "meshbridge/close_gaps.h"
#include "meshbridge/counted.h"
#include "meshbridge/fill_holes.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace meshbridge {

double print_weld_tolerance(const Soup& soup) {
  if (soup.positions.empty())
    return 0;
  Point lo = soup.positions.front(), hi = lo;
  for (const Point& p : soup.positions) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  return std::max(1e-4 * (hi - lo).norm(), default_weld_tolerance(soup, true));
}

void apply_print_preset(const Soup& soup, bool weld_given, bool fill_holes_given,
                        RepairOptions& options) {
  if (!weld_given)
    options.close_gaps.tolerance = print_weld_tolerance(soup);
  options.remove_duplicate_faces = true;
  options.remove_zero_area_faces = true;
  if (!fill_holes_given)
    options.fill_holes.max_edges = kDefaultFillHolesMaxEdges;
}

RepairResult repair_for_print(const Soup& soup, RepairOptions options, std::string& note) {
  note.clear();
  RepairResult result = repair(soup, options);
  const RepairReport& first = result.report;
  const std::size_t duplicates = first.duplicate_faces_removed;
  const std::size_t flat = first.zero_area_faces_removed;
  if (duplicates + flat == 0 || first.boundary_edges_after <= first.boundary_edges_before)
    return result;
  // The removals opened the surface: the first of (zero-area faces kept, duplicates kept, both
  // kept) that leaves no more open edges than the input had, else the one that leaves fewest.
  const std::size_t input_open = first.boundary_edges_before;
  struct Choice {
    bool keep_duplicates, keep_flat;
  };
  for (const Choice choice : {Choice{false, true}, Choice{true, false}, Choice{true, true}}) {
    if ((choice.keep_duplicates && duplicates == 0) || (choice.keep_flat && flat == 0))
      continue;
    RepairOptions kept = options;
    kept.remove_duplicate_faces = !choice.keep_duplicates;
    kept.remove_zero_area_faces = !choice.keep_flat;
    RepairResult trial = repair(soup, kept);
    if (trial.report.boundary_edges_after >= result.report.boundary_edges_after)
      continue;
    std::ostringstream text;
    text << "print: kept the ";
    if (choice.keep_duplicates)
      text << counted(duplicates, "duplicate face") << (choice.keep_flat ? " and the " : "");
    if (choice.keep_flat)
      text << flat << " faces of zero area";
    text << ": removing them left " << counted(first.boundary_edges_after, "open edge")
         << " (keeping them: " << trial.report.boundary_edges_after
         << "; a sheet written twice back to back, which a slicer reads as closed parts of no "
            "volume, or slivers that close a crack)\n";
    note = text.str();
    result = std::move(trial);
    if (result.report.boundary_edges_after <= input_open)
      break;
  }
  return result;
}

}  // namespace meshbridge
