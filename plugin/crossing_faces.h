// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file crossing_faces.h
//! The faces that take part in self-intersections, shown in the defect layer in a third colour
//! beside red (singular) and green (boundary): violet, a copy of each such face lifted a little
//! off both of its sides, so MeshLab draws it over the mesh without depth fighting and from
//! either side.
//!
//! Why violet (140, 0, 255): on MeshLab's grey mesh and its default background it stands out
//! as clearly as the red and green tubes; it is told apart from red and green also by the red-
//! green colour blind (to whom red and green look alike, yellowish, and violet blue), unlike
//! orange or yellow; and it is neither the magenta (255, 0, 255) of pinch-vertex markers nor the
//! orange of "colour faces" at pinch vertices. Knows vcglib's CMeshO and the core, nothing of
//! the plugin API.

#include "cmesh_adapter.h"

#include "meshbridge/self_intersections.h"

#include <cstddef>

namespace meshbridge::meshlab {

//! The colour of faces that cross or overlap another face (also `snapshot`'s, cli/).
inline const vcg::Color4b kCrossingFaceColor(140, 0, 255, 255);

//! How far each copy lies off its face, as a fraction of the inspected mesh's bounding-box
//! diagonal (0.001: a quarter of the defect tubes' default radius, far beyond depth-buffer
//! precision and too small to see as a gap).
inline constexpr double kCrossingFaceLift = 0.001;

//! Appends to `layer` two triangles per triangle of each face of `crossings.faces` (faces of
//! `input.soup`, whose faces are triangles): one lifted by kCrossingFaceLift x diagonal along the
//! face's normal, wound like the face, and one lowered by as much, wound the other way, so each
//! faces away from the face it covers. Every new vertex and face is `colour` (faces only if
//! per-face colour is enabled in `layer`), vertex quality 0. Recomputes the layer's normals and
//! bounding box. Returns how many faces of `input` it covered (faces of zero area are skipped).
//! \throw std::invalid_argument if `crossings` names a face `input` does not have (nothing added)
std::size_t add_crossing_faces(const CMeshSoup& input, const SelfIntersectionReport& crossings,
                               CMeshO& layer, vcg::Color4b color = kCrossingFaceColor);

}  // namespace meshbridge::meshlab
