// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/stock_build.h"
#include "meshbridge/models/canonical_models.h"

#include <gtest/gtest.h>

using namespace meshbridge;

TEST(StockBuild, twocubes_falls_apart_as_design_says) {
  const StockBuild stock = build_stock(models::two_cubes_sharing_edge());
  EXPECT_EQ(stock.report.vertices_created, 38u);
  EXPECT_EQ(stock.report.boundary_edges, 30u);
  EXPECT_EQ(stock.report.components, 10u);
  EXPECT_EQ(stock.report.faces_kept, 24u);
  EXPECT_EQ(stock.report.faces_detached, 8u);
  EXPECT_EQ(stock.report.faces_lost, 0u);
}

TEST(StockBuild, polygons_with_a_repeated_vertex_are_lost) {
  Soup soup = models::bowtie();
  soup.add_polygon({0, 1, 1});
  const StockBuild stock = build_stock(soup);
  EXPECT_EQ(stock.report.faces_lost, 1u);
  EXPECT_EQ(stock.report.faces_kept, 2u);
}

TEST(StockBuild, clean_input_is_kept_whole) {
  const StockBuild stock = build_stock(models::icosphere(1));
  EXPECT_EQ(stock.report.vertices_created, 42u);
  EXPECT_EQ(stock.report.faces_detached, 0u);
  EXPECT_EQ(stock.report.boundary_edges, 0u);
  EXPECT_EQ(stock.report.components, 1u);
}

TEST(StockBuild, without_statistics_the_build_is_the_same) {
  const Soup soup = models::two_cubes_sharing_edge();
  StockBuildOptions options;
  options.count_boundary_and_components = false;
  const StockBuild lean = build_stock(soup, options);
  EXPECT_EQ(lean.report.vertices_created, 38u);
  EXPECT_EQ(lean.report.faces_detached, 8u);
  EXPECT_EQ(lean.report.boundary_edges, 0u);  // not counted
  EXPECT_EQ(lean.report.components, 0u);
  EXPECT_EQ(lean.mesh.n_edges(), build_stock(soup).mesh.n_edges());
}
