// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file cgal_methods.h
//! CGAL's polygon-soup pipeline (Polygon_mesh_processing, CGAL 5.5) on the soup, Epick kernel.

#include "harness.h"

namespace meshbridge::bench {

//! The soup copied to CGAL's soup arrays (points, polygons as index vectors), then
//! repair_polygon_soup, orient_polygon_soup, polygon_soup_to_polygon_mesh (Surface_mesh) and
//! duplicate_non_manifold_vertices, all timed. Output: the Surface_mesh.
void cgal_soup_pipeline(const Soup& soup, Clock& clock, Outcome& outcome);

}  // namespace meshbridge::bench
