// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file stock_build.h
//! The baseline: the soup built the way OpenMesh's own importer builds it.

#include "meshbridge/mesh_types.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <string>

namespace meshbridge {

//! What OpenMesh's stock construction made of a soup.
struct StockBuildReport {
  std::size_t faces_in = 0;
  std::size_t vertices_in = 0;
  std::size_t vertices_created = 0;  //!< vertices of the result (input + duplicates)
  std::size_t faces_kept = 0;        //!< faces present in the result
  std::size_t faces_detached = 0;    //!< refused by add_face, re-added on duplicated vertices
  std::size_t faces_lost = 0;        //!< not in the result at all (e.g. repeated vertex)
  std::size_t boundary_edges = 0;
  std::size_t components = 0;  //!< connected through shared edges of the result
};

struct StockBuild {
  PolyMesh mesh;
  StockBuildReport report;
};

struct StockBuildOptions {
  //! Count boundary edges and components of the result (one pass over its edges). Off: both
  //! stay 0, and the call is exactly OpenMesh's import loop (what benchmarks time).
  bool count_boundary_and_components = true;
};

//! Feeds the soup to OpenMesh's ImporterT (the class its file readers use): add_face, and on
//! refusal the face again on duplicated vertices; polygons with a repeated vertex are dropped.
//! OpenMesh's error stream is muted while it runs.
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element
StockBuild build_stock(const Soup& soup, const StockBuildOptions& options = {});

std::string to_text(const StockBuildReport& report);

}  // namespace meshbridge
