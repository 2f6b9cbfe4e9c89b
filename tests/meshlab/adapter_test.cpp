// SPDX-License-Identifier: GPL-3.0-or-later
// The MeshLab adapter's API-free parts on CMeshO, without MeshLab running: the defect layer's
// tubes, its label, and the log lines MeshLab's rich-text log receives.
#include "defect_tubes.h"
#include "filter_actions.h"

#include "meshbridge/detect_defects.h"

#include <vcg/complex/allocate.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mbm = meshbridge::meshlab;

namespace {

//! A plate of two triangles with a rib triangle standing on their shared diagonal (a T-junction:
//! one singular edge with 3 faces) as a CMeshO.
void t_junction(CMeshO& m) {
  using Alloc = vcg::tri::Allocator<CMeshO>;
  const float p[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1}};
  auto vi = Alloc::AddVertices(m, 5);
  for (const auto& q : p)
    (vi++)->P() = CMeshO::CoordType(q[0], q[1], q[2]);
  const int f[3][3] = {{0, 1, 2}, {0, 2, 3}, {0, 2, 4}};
  auto fi = Alloc::AddFaces(m, 3);
  for (const auto& t : f) {
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &m.vert[std::size_t(t[k])];
    ++fi;
  }
}

std::size_t faces_of_colour(const CMeshO& m, vcg::Color4b c) {
  std::size_t n = 0;
  for (const CFaceO& f : m.face)
    n += (!f.IsD() && f.cC() == c) ? 1 : 0;
  return n;
}

}  // namespace

TEST(DefectTubes, one_tube_per_defect_edge_one_marker_per_singular_vertex) {
  CMeshO mesh;
  t_junction(mesh);
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  const meshbridge::DefectReport report = meshbridge::detect_defects(soup.soup);
  ASSERT_EQ(report.singular_edges.size(), 1u);
  const std::size_t boundary = report.boundary_edges.size();
  const std::size_t markers = report.num_singular_vertices();
  ASSERT_EQ(markers, 2u);

  CMeshO layer;
  layer.face.EnableColor();
  const mbm::DefectLayerCounts counts = mbm::build_defect_tubes(soup, report, layer);
  EXPECT_EQ(counts.singular_edges, 1u);
  EXPECT_EQ(counts.boundary_edges, boundary);
  EXPECT_EQ(counts.singular_vertex_markers, markers);
  const std::size_t tube = mbm::triangles_per_tube({});
  EXPECT_EQ(tube, 12u);
  EXPECT_EQ(std::size_t(layer.fn), tube * (1 + boundary) + mbm::kTrianglesPerMarker * markers);
  EXPECT_EQ(std::size_t(layer.vn), 12 * (1 + boundary) + 6 * markers);
  EXPECT_EQ(faces_of_colour(layer, vcg::Color4b::Red), tube + 8 * markers);
  EXPECT_EQ(faces_of_colour(layer, vcg::Color4b::Green), tube * boundary);
  EXPECT_EQ(layer.en, 0);
  // Thin: markers reach 1.4% of the diagonal past a vertex, so the box grows by at most
  // 2 * 0.014 * sqrt(3) of the diagonal.
  const float diag = std::sqrt(3.0f);
  EXPECT_LT(layer.bbox.Diag(), diag * 1.05f);
  EXPECT_GT(layer.bbox.Diag(), diag);
  // The inspected mesh is untouched: no colour turned on, nothing selected.
  EXPECT_FALSE(mesh.face.IsColorEnabled());
  EXPECT_EQ(mesh.fn, 3);
}

TEST(DefectTubes, bad_report_leaves_layer_empty) {
  CMeshO mesh;
  t_junction(mesh);
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  meshbridge::DefectReport report = meshbridge::detect_defects(soup.soup);
  report.pinch_vertices.push_back(99);
  CMeshO layer;
  EXPECT_THROW(mbm::build_defect_tubes(soup, report, layer), std::invalid_argument);
  EXPECT_EQ(layer.vn, 0);
  EXPECT_EQ(layer.fn, 0);
}

TEST(DefectLayerLabel, drops_extension_and_inner_dots) {
  EXPECT_EQ(mbm::defect_layer_label("t_junction_rib.off"), "t_junction_rib - defects");
  EXPECT_EQ(mbm::defect_layer_label("part.v2.stl"), "part_v2 - defects");
  EXPECT_EQ(mbm::defect_layer_label("scan"), "scan - defects");
  EXPECT_EQ(mbm::defect_layer_label("a (copy).x y"), "a (copy)_x y - defects");
}

TEST(HtmlLogLines, escapes_and_splits_every_line) {
  const std::vector<std::string> lines =
      mbm::html_log_lines("a <b> & c\n  faces set aside (< 3 distinct vertices): 0\n\nlast\n\n");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "a &lt;b&gt; &amp; c");
  EXPECT_EQ(lines[1], "  faces set aside (&lt; 3 distinct vertices): 0");
  EXPECT_EQ(lines[2], "");
  EXPECT_EQ(lines[3], "last");
}
