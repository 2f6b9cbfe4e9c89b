// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file cmesh_adapter.h
//! CMeshO (MeshLab's vcglib mesh) <-> meshbridge core.
//!
//! Knows vcglib's CMeshO and the core, nothing of MeshLab's plugin API, so every MeshLab adapter
//! (2020.09's MeshFilterInterface, 2022+'s FilterPlugin) shares it. Data masks, logging and
//! parameters are the API glue's business.

// CMeshO: MeshLab 2020.09 declares it in common/ml_mesh_type.h, 2022+ in ml_document/cmesh.h.
#if __has_include(<common/ml_document/cmesh.h>)
#include <common/ml_document/cmesh.h>
#else
#include <common/ml_mesh_type.h>
#endif

#include "meshbridge/defect_report.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace meshbridge::meshlab {

//! The live elements of a CMeshO as a soup, and where each came from.
struct CMeshSoup {
  Soup soup;  //!< one triangle per live face, in storage order; positions widened to double
  std::vector<CMeshO::VertexPointer> vertices;  //!< #V: soup vertex -> CMeshO vertex
  std::vector<CMeshO::FacePointer> faces;       //!< #F: soup face -> CMeshO face
};

//! Every live vertex (isolated ones too) and every live face of `m`, in storage order.
//! Deleted elements are skipped; nothing in `m` changes.
CMeshSoup soup_from_cmesh(CMeshO& m);

//! A CMeshO position as the core's soups hold it (float widened to double).
inline Point widened(const CMeshO::CoordType& p) {
  return Point(double(p[0]), double(p[1]), double(p[2]));
}

//! How write_repaired() treats what the core did not hand back.
struct WriteBackOptions {
  //! Put back the faces the core set aside (fewer than 3 distinct corners), unchanged, at their
  //! place in face order, on the first copy of each of their vertices. Off: they are dropped.
  bool keep_set_aside_faces = true;
  //! True: face normals are left for the caller to recompute. False: face normals are copied
  //! and negated on flipped faces (vertex normals are always copied from the original vertex).
  bool recompute_normals = true;
  //! Also hand back the rebuilt mesh as a soup (WriteBackReport::soup), made while writing, so a
  //! caller that checks the result needs no second soup_from_cmesh(). Default: off.
  bool keep_soup = false;
};

//! What write_repaired() did besides copying the core's result.
struct WriteBackReport {
  std::size_t faces_in = 0;      //!< live faces of `m` before
  std::size_t faces_out = 0;     //!< faces of `m` after
  std::size_t vertices_in = 0;   //!< live vertices of `m` before
  std::size_t vertices_out = 0;  //!< vertices of `m` after
  //! faces the core set aside (in a triangle layer: degenerate, a vertex repeated), put back
  //! unchanged
  std::size_t degenerate_faces_kept = 0;
  //! output polygons with more than 3 corners, cut into triangles as the STL and 3MF writers cut
  //! them (triangles_as_written(): ear clipping, no diagonal on an existing edge)
  std::size_t polygons_triangulated = 0;
  std::size_t triangles_added_by_triangulation = 0;  //!< extra triangles those polygons made
  std::size_t faces_flipped = 0;                     //!< triangles whose corner order was reversed
  std::size_t faces_added = 0;  //!< faces with no input face (hole filling), last
  //! With WriteBackOptions::keep_soup: `m` after the write-back, exactly as
  //! soup_from_cmesh(m).soup would give it (positions as `m` stores them, widened to double).
  std::optional<Soup> soup;
};

//! Replaces the content of `m` with `repaired` (the result of repairing `input.soup`).
//!
//! Every output vertex takes all attributes of its original (colour, quality, normal, texture
//! coordinate, flags, optional components), so split copies carry their original's data. Every
//! output face takes all attributes of its original face (colour, quality, normal, flags) and
//! its wedge texture coordinates follow `corner_origin`; faux-edge flags follow their edge. Face
//! order is `repaired`'s (which preserves the input's). A face with `face_origin` kNoIndex (added
//! by hole filling; its corners have `corner_origin` kNoIndex) comes after every face of the
//! input and gets no flags, the default colour (opaque black, as in files) and quality 0, wedge
//! texture coordinates of an input face's corner at the same vertex, and (if normals are not
//! recomputed) its geometric normal. Border flags are cleared; adjacency, bounding box, normals
//! and selection counts are left to the caller.
//! \pre `input` is soup_from_cmesh(m) and `m` has not changed since.
//! \throw std::invalid_argument if `repaired` does not fit `input` (then `m` is unchanged)
WriteBackReport write_repaired(CMeshO& m, const CMeshSoup& input, const IndexedMesh& repaired,
                               const std::vector<Index>& set_aside_faces,
                               const WriteBackOptions& options = {});

//! Colours of the defect layer (MeshLab's own convention: non-manifold red, border green).
struct DefectColors {
  vcg::Color4b singular_edge = vcg::Color4b::Red;
  vcg::Color4b boundary_edge = vcg::Color4b::Green;
  vcg::Color4b singular_edge_vertex = vcg::Color4b::Red;  //!< marker point
  vcg::Color4b pinch_vertex = vcg::Color4b::Magenta;      //!< marker point
};

//! What build_defect_layer() put in the layer.
struct DefectLayerCounts {
  std::size_t singular_edges = 0;
  std::size_t boundary_edges = 0;
  std::size_t singular_vertex_markers = 0;
};

//! Fills `layer` (cleared first) with an edge mesh of the defects of `input`: per singular edge
//! and per boundary edge two new vertices and one edge, coloured per vertex (CEdgeO has no
//! colour), vertex quality = contenders on the edge; then one isolated, selected marker vertex
//! per singular vertex (quality 0). No faces. `layer` must not be `input`'s mesh.
DefectLayerCounts build_defect_layer(const CMeshSoup& input, const DefectReport& report,
                                     CMeshO& layer, const DefectColors& colors = {});

//! What select_defect_faces() selected.
struct DefectSelection {
  std::size_t faces = 0;     //!< faces with a side on a singular edge or a corner at a pinch vertex
  std::size_t vertices = 0;  //!< singular vertices
};

//! Replaces the face and vertex selection of `input`'s mesh by the faces with a side on a
//! singular edge or a corner at a pinch vertex, and the singular vertices. With `colour_faces`
//! those faces also get `singular_edge` (red) or `pinch` (orange) colour; the caller enables
//! per-face colour first.
DefectSelection select_defect_faces(CMeshSoup& input, const DefectReport& report, bool select,
                                    bool color_faces,
                                    vcg::Color4b singular_edge = vcg::Color4b::Red,
                                    vcg::Color4b pinch = vcg::Color4b(255, 128, 0, 255));

}  // namespace meshbridge::meshlab
