// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The invariants of a repair, checked without a test framework: any violation prints what broke
// and aborts, which is how libFuzzer learns of it.

#include "meshbridge/detect_defects.h"
#include "meshbridge/edge_bridges.h"
#include "meshbridge/mesh_types.h"
#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace meshbridge::fuzz {

[[noreturn]] inline void fail(const char* what, std::size_t a = 0, std::size_t b = 0) {
  std::fprintf(stderr, "meshbridge invariant violated: %s (%zu, %zu)\n", what, a, b);
  std::abort();
}

inline void check(bool ok, const char* what, std::size_t a = 0, std::size_t b = 0) {
  if (!ok)
    fail(what, a, b);
}

//! Every edge of `soup` has at most two sides, and two sides run opposite ways.
inline void check_every_edge_manifold(const Soup& soup) {
  const std::vector<Index> corner_face = corner_faces(soup);
  const EdgeBridges bridges = group_sides(soup, corner_face);
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    const auto [v0, v1] = bridges.edge_vertices(e, soup, corner_face);
    check(k <= 2, "output edge with more than two sides", v0, v1);
    if (k == 2) {
      const Index a = bridges.contenders[bridges.begin[e]];
      const Index b = bridges.contenders[bridges.begin[e] + 1];
      check(soup.corner_vertices[a] != soup.corner_vertices[b],
            "output edge with two sides running the same way", v0, v1);
    }
  }
}

//! Everything `repair(input, options)` promises about `result`.
inline void check_repair(const Soup& input, const RepairOptions& options,
                         const RepairResult& result) {
  const IndexedMesh& mesh = result.mesh;
  const RepairReport& r = result.report;
  // Nothing lost: every face is kept, set aside (listed) or removed by a cleanup option.
  check(r.faces_in == input.num_faces(), "faces_in", r.faces_in, input.num_faces());
  check(r.faces_out + r.faces_set_aside + r.duplicate_faces_removed + r.degenerate_faces_removed ==
            input.num_faces() + r.faces_added_by_split,
        "faces out + set aside + removed != faces in + added by split", r.faces_out,
        input.num_faces());
  check(options.remove_duplicate_faces || r.duplicate_faces_removed == 0,
        "duplicates removed without the option");
  check(options.remove_degenerate_faces || r.degenerate_faces_removed == 0,
        "degenerate faces removed without the option");
  check(options.remove_isolated_vertices || r.isolated_vertices_removed == 0,
        "isolated vertices removed without the option");
  check(mesh.soup.num_faces() == r.faces_out, "faces_out", mesh.soup.num_faces(), r.faces_out);
  check(mesh.soup.num_vertices() == r.vertices_out, "vertices_out");
  check(mesh.face_origin.size() == mesh.soup.num_faces(), "face_origin size");
  check(mesh.corner_origin.size() == mesh.soup.num_corners(), "corner_origin size");
  check(mesh.vertex_origin.size() == mesh.soup.num_vertices(), "vertex_origin size");
  check(std::is_sorted(mesh.face_origin.begin(), mesh.face_origin.end()), "face order changed");
  for (std::size_t f = 0; f < mesh.soup.num_faces(); ++f) {
    check(mesh.face_origin[f] < input.num_faces(), "face origin out of range", f);
    check(mesh.soup.arity(f) >= 3, "output polygon with fewer than 3 corners", f);
  }
  // Provenance: same positions, corners come from corners of the same input vertex.
  // A vertex with no origin (kNoIndex) is the midpoint of an edge split to stay manifold.
  std::size_t midpoints = 0;
  for (std::size_t v = 0; v < mesh.soup.num_vertices(); ++v) {
    if (mesh.vertex_origin[v] == kNoIndex) {
      ++midpoints;
      continue;
    }
    check(mesh.vertex_origin[v] < input.num_vertices(), "vertex origin out of range", v);
    check(mesh.soup.positions[v] == input.positions[mesh.vertex_origin[v]],
          "position differs from its origin", v);
  }
  check(midpoints == r.edges_split_to_stay_manifold, "vertices without origin", midpoints,
        r.edges_split_to_stay_manifold);
  // A corner keeps its input vertex, except where gap closing changed the soup: a welded
  // corner moves to its weld's survivor (at most the reported largest weld distance away), and a
  // corner inserted to close a T-junction takes the corner starting the side it split as origin
  // (one per closed T-junction may lie anywhere).
  std::size_t inserted = 0;
  for (std::size_t c = 0; c < mesh.soup.num_corners(); ++c) {
    check(mesh.soup.corner_vertices[c] < mesh.soup.num_vertices(), "corner index out of range", c);
    check(mesh.corner_origin[c] < input.num_corners(), "corner origin out of range", c);
    const Index from = input.corner_vertices[mesh.corner_origin[c]];
    const Index to = mesh.vertex_origin[mesh.soup.corner_vertices[c]];
    if (to == from || to == kNoIndex)  // kNoIndex: a midpoint corner
      continue;
    check(r.gaps.changed(), "corner comes from another vertex", c);
    if ((input.positions[to] - input.positions[from]).norm() > r.gaps.largest_weld_distance)
      ++inserted;
  }
  check(inserted <= r.gaps.t_junctions_closed, "corner moved farther than any weld", inserted,
        r.gaps.t_junctions_closed);
  check(r.gaps.tolerance == 0 || r.gaps.largest_weld_distance <= r.gaps.tolerance,
        "weld farther than the tolerance");
  // Manifold: by our grouping, by an independent detection, and by OpenMesh.
  check_every_edge_manifold(mesh.soup);
  const DefectReport after = detect_defects(mesh.soup);
  check(after.singular_edges.empty(), "singular edge after repair", after.singular_edges.size());
  check(after.num_singular_vertices() == 0, "singular vertex after repair",
        after.num_singular_vertices());
  check(after.inconsistent_edges.empty(), "inconsistent edge after repair",
        after.inconsistent_edges.size());
  check(after.degenerate_faces.empty(), "degenerate face after repair",
        after.degenerate_faces.size());
  if (options.detect_before_after) {
    check(r.after.singular_edges.size() == after.singular_edges.size(), "report.after differs");
    check(r.after.boundary_edges.size() == after.boundary_edges.size(), "report.after differs");
    check(r.after.num_components == after.num_components, "report.after differs");
  }
  const OpenMeshBuild build = to_openmesh(mesh);
  check(build.add_face_failures == 0, "OpenMesh refused a face", build.add_face_failures);
  check(build.mesh.n_faces() == mesh.soup.num_faces(), "OpenMesh lost faces");
  for (auto v : build.mesh.vertices())
    check(build.mesh.is_manifold(v), "OpenMesh vertex not manifold", std::size_t(v.idx()));
}

//! Repairing the output again with the same options changes nothing. Gap closing is left out
//! of the second repair: where its tolerance spans whole features (an outlier far from the
//! rest makes the automatic one wide), the first repair's splits and welds can bring more
//! vertices within it, so a second run may weld again.
inline void check_idempotent(RepairOptions options, const RepairResult& once) {
  options.close_gaps.tolerance = 0;
  const RepairResult twice = repair(once.mesh.soup, options);
  check_repair(once.mesh.soup, options, twice);
  check(twice.mesh.soup.positions == once.mesh.soup.positions, "second repair moved vertices");
  // Known limit: a midpoint vertex changes how a polygon is cut into triangles for a shell's
  // volume; where coordinates span more than 1e12 x the shortest edge (1e18 next to 1), that
  // volume sits at its rounding bound, and whether the shell counts as one (and so its nesting
  // and winding) can change on the second repair. Only the corner order may differ then.
  if (once.report.edges_split_to_stay_manifold > 0) {
    const Soup& s = once.mesh.soup;
    double largest = 0, shortest = std::numeric_limits<double>::infinity();
    for (const Point& p : s.positions)
      largest = std::max({largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    for (Index f = 0; f < s.num_faces(); ++f) {
      for (Index c = s.face_begin[f]; c < s.face_begin[f + 1]; ++c) {
        const double length = (s.positions[s.corner_vertices[c]] -
                               s.positions[s.corner_vertices[s.next_corner(c, f)]])
                                  .norm();
        if (length > 0)
          shortest = std::min(shortest, length);
      }
    }
    if (largest > 1e12 * shortest)
      return;
  }
  check(twice.mesh.soup.corner_vertices == once.mesh.soup.corner_vertices,
        "second repair changed corners");
  check(twice.mesh.soup.face_begin == once.mesh.soup.face_begin, "second repair changed faces");
  check(twice.report.vertices_split == 0, "second repair split vertices",
        twice.report.vertices_split);
  check(twice.report.faces_flipped == 0, "second repair flipped faces", twice.report.faces_flipped);
  check(twice.report.sides_cut == 0, "second repair cut sides");
}

}  // namespace meshbridge::fuzz
