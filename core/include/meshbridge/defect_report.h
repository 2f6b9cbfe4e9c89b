// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file defect_report.h
//! What detection finds: counts and element lists, printable as text (JSON: report_json.h).

#include "meshbridge/soup.h"

#include <cstddef>
#include <string>
#include <vector>

namespace meshbridge {

//! An undirected vertex pair, `v0 < v1`.
struct VertexPair {
  Index v0 = kNoIndex;
  Index v1 = kNoIndex;
  friend bool operator==(const VertexPair& a, const VertexPair& b) {
    return a.v0 == b.v0 && a.v1 == b.v1;
  }
  friend bool operator<(const VertexPair& a, const VertexPair& b) {
    return a.v0 != b.v0 ? a.v0 < b.v0 : a.v1 < b.v1;
  }
};

//! An edge with more than two polygon sides on it.
struct SingularEdge {
  VertexPair vertices;
  Index contenders = 0;  //!< number of polygon sides on the edge (> 2)
};

//! The defects of a soup, as the user sees the model (through all contenders).
struct DefectReport {
  std::size_t num_vertices = 0;  //!< positions in the soup (isolated ones included)
  std::size_t num_faces = 0;     //!< polygons in the soup
  std::size_t num_edges = 0;     //!< distinct vertex pairs carrying at least one polygon side

  std::vector<SingularEdge> singular_edges;   //!< edges with > 2 contenders
  std::vector<Index> singular_edge_vertices;  //!< endpoints of singular edges
  std::vector<Index> pinch_vertices;          //!< singular vertices on no singular edge
  std::vector<VertexPair> boundary_edges;     //!< edges with exactly 1 contender
  std::size_t num_boundary_loops = 0;         //!< holes: connected chains of boundary edges
  std::vector<Index> isolated_vertices;       //!< vertices used by no polygon
  //! polygons with a repeated vertex index, keyhole polygons not among them (counted once, in
  //! keyhole_polygons_triangulated)
  std::vector<Index> degenerate_faces;
  std::vector<Index> faces_set_aside;  //!< degenerate ones with < 3 distinct corners
  //! Keyhole slits: two-corner pieces of pinched polygons (the polygon runs a -> b and later
  //! b -> a). Every slit's edge counts in num_edges and joins the polygon's loops in
  //! num_components, as in the file. A polygon that is an outline with holes joined by its slits
  //! is triangulated by repair as one polygon with holes (its triangles hold the slits; counted
  //! here and in RepairReport::keyhole_polygons_triangulated); the slits of other polygons (a
  //! slit to a loop outside the outline) no face can hold, and repair sets them aside (counted
  //! here and in RepairReport::slits_set_aside).
  std::size_t slits_set_aside = 0;
  std::size_t keyhole_polygons_triangulated = 0;
  std::vector<Index> zero_area_faces;            //!< polygons whose area is ~0 (see detect_defects)
  std::vector<Index> duplicate_faces;            //!< polygons whose vertex set an earlier one has
  std::vector<VertexPair> inconsistent_edges;    //!< 2-sided edges whose sides run the same way
  std::size_t num_nonorientable_components = 0;  //!< components that no flipping makes consistent
  std::size_t num_components = 0;                //!< connected through every contender
  //! V - E + F over the used vertices, with F the faces detection works on: a pinched polygon
  //! counts as its simple loops (as repair splits it), one with < 3 distinct corners not at all,
  //! a keyhole polygon repair triangulates as one face (V - E + F of its triangles is the same).
  //! So F may differ from num_faces, which counts the file's polygons.
  long long euler_characteristic = 0;
  bool watertight = false;  //!< closed 2-manifold: no boundary, singular or inconsistent element
  //! Face records of the file with no corner at all, so in no soup (set by
  //! count_records_without_corners(), 0 for a soup alone): counted in the reports' `faces` and
  //! `faces_set_aside` (num_faces() and num_faces_set_aside()) and a defect, as the faces set
  //! aside of the soup are; the element lists cannot name them.
  std::size_t records_without_corners = 0;

  //! The soup's polygons and the records without corners: the faces of the file.
  std::size_t num_faces_of_file() const { return num_faces + records_without_corners; }
  //! Faces set aside (< 3 distinct corners), the records without corners included.
  std::size_t num_faces_set_aside() const {
    return faces_set_aside.size() + records_without_corners;
  }

  std::size_t num_singular_vertices() const {
    return singular_edge_vertices.size() + pinch_vertices.size();
  }
  //! True if anything above needs attention. Not defects: components, Euler number, zero-area
  //! faces with 3 distinct corners and isolated vertices (listed only: repair keeps both on
  //! purpose, the faces as valid topology and the vertices as data no face loses, so a `check`
  //! of a repaired file can exit 0; a vertex only a set-aside face used stays as such a vertex).
  //! `check` exits 1 exactly when this is true.
  bool has_defects() const;
};

//! Human-readable block of counts, followed by the first `max_listed` elements of each list.
std::string to_text(const DefectReport& report, std::size_t max_listed = 10);

}  // namespace meshbridge
