// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/bridged_mesh.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/stock_build.h"

#include "test_support.h"

#include <gtest/gtest.h>

using namespace meshbridge;

TEST(BridgedMesh, every_canonical_face_is_added_and_every_vertex_is_manifold) {
  for (const auto& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    for (PairingPolicy policy : {PairingPolicy::geometric, PairingPolicy::combinatorial}) {
      const BridgedMesh bridged = build_bridged_mesh(model.soup, {policy});
      EXPECT_EQ(bridged.mesh.n_faces(), model.soup.num_faces());
      for (auto v : bridged.mesh.vertices())
        EXPECT_TRUE(bridged.mesh.is_manifold(v));
      EXPECT_TRUE(test_support::every_edge_manifold(bridged.indexed.soup));
    }
  }
}

TEST(BridgedMesh, twocubes_splits_the_two_shared_vertices_once_each) {
  const Soup soup = models::two_cubes_sharing_edge();
  const BridgedMesh bridged = build_bridged_mesh(soup);
  EXPECT_EQ(bridged.mesh.n_vertices(), 16u);
  EXPECT_EQ(bridged.mesh.n_faces(), 24u);
  std::size_t boundary = 0;
  for (auto e : bridged.mesh.edges())
    boundary += bridged.mesh.is_boundary(e);
  EXPECT_EQ(boundary, 0u);
  // The vertex bridge: the two ends of the shared edge have two copies each.
  std::size_t split = 0;
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    const auto copies = bridged.copies_of(v);
    ASSERT_GE(copies.size(), 1u);
    EXPECT_EQ(copies.front(), v);
    if (copies.size() > 1)
      ++split;
    for (Index c : copies)
      EXPECT_EQ(bridged.indexed.vertex_origin[c], v);
  }
  EXPECT_EQ(split, 2u);
  // The edge bridge keeps all four contenders of the shared edge, in two pairs.
  std::size_t singular = 0;
  for (std::size_t e = 0; e < bridged.bridges.num_edges(); ++e) {
    if (bridged.bridges.num_contenders(e) != 4)
      continue;
    ++singular;
    for (Index i = bridged.bridges.begin[e]; i < bridged.bridges.begin[e + 1]; ++i) {
      EXPECT_NE(bridged.mate[bridged.bridges.contenders[i]], kNoIndex);
    }
  }
  EXPECT_EQ(singular, 1u);
}

TEST(BridgedMesh, clean_input_is_exactly_what_openmesh_builds) {
  for (const Soup& soup :
       {models::icosphere(2), models::torus_grid(12, 9), models::cube_with_hole()}) {
    const BridgedMesh bridged = build_bridged_mesh(soup);
    const StockBuild stock = build_stock(soup);
    EXPECT_EQ(bridged.mesh.n_vertices(), stock.mesh.n_vertices());
    EXPECT_EQ(bridged.mesh.n_faces(), stock.mesh.n_faces());
    EXPECT_EQ(bridged.mesh.n_edges(), stock.mesh.n_edges());
    EXPECT_EQ(stock.report.faces_detached, 0u);
    for (auto f : bridged.mesh.faces()) {
      auto a = bridged.mesh.fv_range(f).begin();
      auto b = stock.mesh.fv_range(stock.mesh.face_handle(f.idx())).begin();
      for (std::size_t i = 0; i < bridged.mesh.valence(f); ++i, ++a, ++b) {
        EXPECT_EQ((*a).idx(), (*b).idx());
      }
    }
  }
}

TEST(BridgedMesh, openmesh_properties_give_provenance) {
  const BridgedMesh bridged = build_bridged_mesh(models::bowtie());
  OpenMesh::VPropHandleT<Index> vertex_origin;
  ASSERT_TRUE(bridged.mesh.get_property_handle(vertex_origin, kVertexOriginProperty));
  EXPECT_EQ(bridged.mesh.n_vertices(), 6u);
  EXPECT_EQ(bridged.mesh.property(vertex_origin, OpenMesh::VertexHandle(5)), 0u);
}
