// SPDX-License-Identifier: GPL-3.0-or-later
#include "print_summary.h"

#include "meshbridge/counted.h"
#include "meshbridge/fill_holes.h"

#include <sstream>

namespace meshbridge::cli {

std::string print_summary(const RepairReport& r, const DefectReport* written) {
  std::ostringstream out;
  const DefectReport& after = written != nullptr ? *written : r.after;
  out << "print: " << (after.watertight ? "watertight" : "not watertight") << " as written";
  if (!after.singular_edges.empty()) {
    out << "; " << counted(after.singular_edges.size(), "singular edge")
        << " in the written triangles (polygons split at an edge's midpoint on both sides of one "
           "sheet share a diagonal)";
  }
  if (r.duplicate_faces_removed > 0)
    out << "; removed " << counted(r.duplicate_faces_removed, "duplicate face");
  if (r.zero_area_faces_removed > 0)
    out << "; removed " << counted(r.zero_area_faces_removed, "face") << " of zero area";
  if (r.faces_set_aside > 0)
    out << "; " << counted(r.faces_set_aside, "face")
        << " of no area (< 3 distinct corners) set aside";
  out << "\n";
  if (after.boundary_edges.empty())
    return out.str();
  out << "print: " << counted(after.boundary_edges.size(), "open edge") << " in "
      << counted(after.num_boundary_loops, "boundary loop") << " left:";
  const FillHolesReport& h = r.holes;
  const std::size_t too_long = h.holes_left - h.patches_refused;
  std::string separator = " ";
  if (too_long > 0) {
    out << separator << too_long << (too_long == 1 ? " hole is" : " holes are") << " longer than "
        << h.max_edges << " edges (--fill-holes N fills longer ones)";
    separator = "; ";
  }
  if (h.patches_refused > 0) {
    out << separator << counted(h.patches_refused, "loop")
        << " outlining an open sheet (no hole: a patch would lie on the surface)";
    separator = "; ";
  }
  std::size_t odd = 0;
  for (const SingularEdge& e : r.before.singular_edges)
    odd += e.contenders % 2;
  if (odd > 0) {
    out << separator << counted(odd, "singular edge")
        << " of the input with an odd number of faces (one face on each stays open)";
    separator = "; ";
  }
  if (!r.gaps.refused_reason.empty()) {
    out << separator << "gap closing refused (" << r.gaps.refused_reason << ")";
    separator = "; ";
  }
  if (separator == " ")
    out << " the input's own boundary (no hole of " << h.max_edges << " edges or fewer)";
  out << "\n";
  return out.str();
}

std::string open_edges_hint(const RepairReport& r) {
  if (r.after.boundary_edges.empty())
    return "";
  std::ostringstream out;
  out << "hint: " << counted(r.after.boundary_edges.size(), "open edge") << " in "
      << counted(r.after.num_boundary_loops, "boundary loop") << " left; ";
  if (r.holes.max_edges == 0)
    out << "--fill-holes closes holes of up to " << kDefaultFillHolesMaxEdges << " edges, and ";
  out << "--print (OUT.3mf) is the slicer preset that says why each stays open\n";
  return out.str();
}

}  // namespace meshbridge::cli
