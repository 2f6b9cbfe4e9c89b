// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file defect_tubes.h
//! The defect layer as a triangle mesh that every MeshLab renderer shows in colour without being
//! asked: a thin tube along each singular edge (red) and each boundary edge (green), and a small
//! marker at each singular vertex (red on singular edges, magenta at pinch vertices).
//!
//! MeshLab (2020.09 and 2022+) draws a new layer with faces as a lit solid in its per-vertex
//! colour, and draws edge meshes as 1-pixel lines in a user colour; tubes around an edge also
//! stick out of the faces that lie on it (a T-junction's edge in a concave corner included), so
//! the defects are visible by default. Knows vcglib's CMeshO and the core, nothing of the plugin
//! API.

#include "cmesh_adapter.h"

#include "meshbridge/defect_report.h"

#include <cstddef>

namespace meshbridge::meshlab {

//! Sizes and shapes of the tube layer.
struct DefectTubeOptions {
  //! Tube radius as a fraction of the inspected mesh's bounding-box diagonal. Default 0.004:
  //! about 8 pixels across when the whole model fills a 1000-pixel viewport.
  double radius_fraction = 0.004;
  //! Marker (octahedron) radius as a multiple of the tube radius. Default 3.5 (a marker shows
  //! beside a tube that lies in front of it).
  double marker_scale = 3.5;
  //! Sides of each tube's cross-section (>= 3). Default 6.
  int sides = 6;
  //! Sized from the geometry around each defect, never larger than what it marks: a tube's
  //! radius is at most this fraction of its own edge's length (default 0.1), so tubes on 5 mm
  //! letters stay thinner than the letters on a 220 mm bed.
  double tube_edge_fraction = 0.1;
  //! A marker's radius is at most this fraction of the shortest edge at its vertex (default
  //! 0.3), so it never covers a neighbouring vertex.
  double marker_edge_fraction = 0.3;
};

//! Triangles per tube (`2 * sides`, open ends) and per marker (8, an octahedron).
std::size_t triangles_per_tube(const DefectTubeOptions& options);
inline constexpr std::size_t kTrianglesPerMarker = 8;

//! Fills `layer` (cleared first) with one tube per singular edge and per boundary edge of
//! `report` (which describes `input`), then one marker per singular vertex: vertices
//! `(2 * sides) * edges + 6 * markers`, triangles `triangles_per_tube * edges + 8 * markers`,
//! in this order: singular edges, boundary edges, singular-edge vertices, pinch vertices. Every
//! vertex and face of a tube or marker carries its colour (per-vertex and, if enabled in
//! `layer`, per-face colour), vertex quality = sides on the edge (contenders; 0 for markers);
//! face and vertex normals are computed. Each tube reaches one radius past both ends, so tubes
//! meeting at a vertex close the joint. `layer` must not be `input`'s mesh.
//! \throw std::invalid_argument if the report names a vertex `input` does not have, or
//!        `options.sides < 3` (then `layer` is empty)
DefectLayerCounts build_defect_tubes(const CMeshSoup& input, const DefectReport& report,
                                     CMeshO& layer, const DefectTubeOptions& options = {},
                                     const DefectColors& colors = {});

}  // namespace meshbridge::meshlab
