// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/separate_copies.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

using namespace meshbridge;

namespace {

// The soup an STL reader makes of `mesh`: vertices welded by exact position.
Soup welded(const IndexedMesh& mesh) {
  Soup soup;
  std::vector<Index> index(mesh.soup.num_vertices());
  for (std::size_t v = 0; v < mesh.soup.num_vertices(); ++v) {
    index[v] = kNoIndex;
    for (std::size_t w = 0; w < soup.num_vertices(); ++w) {
      if (soup.positions[w] == mesh.soup.positions[v])
        index[v] = static_cast<Index>(w);
    }
    if (index[v] == kNoIndex)
      index[v] = soup.add_vertex(mesh.soup.positions[v]);
  }
  std::vector<Index> polygon;
  for (std::size_t f = 0; f < mesh.soup.num_faces(); ++f) {
    polygon.clear();
    for (Index v : mesh.soup.polygon(f))
      polygon.push_back(index[v]);
    soup.add_polygon(polygon);
  }
  return soup;
}

}  // namespace

TEST(SeparateSplitVertices, repair_survives_welding_by_position) {
  RepairResult r = repair(models::two_cubes_sharing_edge());
  EXPECT_EQ(detect_defects(welded(r.mesh)).singular_edges.size(), 1u);  // welding undoes it
  const auto before = r.mesh.soup.positions;
  EXPECT_EQ(separate_split_vertices(r.mesh, 1e-3), 4u);  // both copies of both shared vertices
  const DefectReport after = detect_defects(welded(r.mesh));
  EXPECT_TRUE(after.singular_edges.empty());
  EXPECT_EQ(after.num_singular_vertices(), 0u);
  EXPECT_TRUE(after.watertight);
  for (std::size_t v = 0; v < before.size(); ++v) {
    EXPECT_LE((r.mesh.soup.positions[v] - before[v]).norm(), 1e-3 + 1e-15);
  }
}

TEST(SeparateSplitVertices, nothing_moves_without_split_vertices_or_distance) {
  RepairResult r = repair(models::icosphere(1));
  EXPECT_EQ(separate_split_vertices(r.mesh, 1e-3), 0u);
  RepairResult cubes = repair(models::two_cubes_sharing_edge());
  EXPECT_EQ(separate_split_vertices(cubes.mesh, 0.0), 0u);
}

TEST(SeparateSplitVertices, bad_arguments_are_rejected) {
  RepairResult r = repair(models::bowtie());
  EXPECT_THROW(separate_split_vertices(r.mesh, -1.0), std::invalid_argument);
  EXPECT_THROW(separate_split_vertices(r.mesh, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  r.mesh.vertex_origin.pop_back();
  EXPECT_THROW(separate_split_vertices(r.mesh, 1e-3), std::invalid_argument);
}
