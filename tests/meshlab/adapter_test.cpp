// SPDX-License-Identifier: GPL-3.0-or-later
// The MeshLab adapter's API-free parts on CMeshO, without MeshLab running: the defect layer's
// tubes, its label, the log lines MeshLab's rich-text log receives, the parameter catalogue,
// what the filters log about gap closing and STL, and the write-back of faces that hole filling
// added, and the fans of polygons with a side split at its midpoint.
#include "cmesh_adapter.h"
#include "defect_tubes.h"
#include "fake_host.h"
#include "filter_actions.h"
#include "filter_catalog.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include <vcg/complex/allocate.h>

#include <gtest/gtest.h>

#include <string>
#include <utility>
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

const mbm::ParameterSpec* find_parameter(mbm::FilterId id, const std::string& name) {
  for (const mbm::ParameterSpec& p : mbm::parameters(id)) {
    if (name == p.name)
      return &p;
  }
  return nullptr;
}

bool has_line(const std::string& log, const std::string& line) {
  return ("\n" + log + "\n").find("\n" + line + "\n") != std::string::npos;
}

//! The unit cube without its top (z = 1) as 10 outward triangles, each face coloured (10 * f, 0,
//! 0), with per-face colour and wedge texture coordinates (u = vertex number / 10) enabled.
void open_box(CMeshO& m) {
  using Alloc = vcg::tri::Allocator<CMeshO>;
  auto vi = Alloc::AddVertices(m, 8);
  for (int c = 0; c < 8; ++c)
    (vi++)->P() = CMeshO::CoordType(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
  const int quads[5][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  m.face.EnableColor();
  m.face.EnableWedgeTexCoord();
  auto fi = Alloc::AddFaces(m, 10);
  for (const auto& q : quads) {
    const int triangles[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
    for (const auto& t : triangles) {
      for (int k = 0; k < 3; ++k) {
        fi->V(k) = &m.vert[std::size_t(t[k])];
        fi->WT(k).U() = float(t[k]) / 10;
      }
      fi->C() = vcg::Color4b(static_cast<unsigned char>(10 * (fi - m.face.begin())), 0, 0, 255);
      ++fi;
    }
  }
}

std::size_t faces_of_color(const CMeshO& m, vcg::Color4b c) {
  std::size_t n = 0;
  for (const CFaceO& f : m.face)
    n += (!f.IsD() && f.cC() == c) ? 1 : 0;
  return n;
}

}  // namespace

TEST(DefectTubes, sized_from_the_geometry_around_each_defect_not_the_bounding_box) {
  // A 220 x 220 bed (two triangles) and, in its corner, a bowtie 5 units across: its pinch
  // vertex's marker and its edges' tubes stay within the bowtie, not 3.5 * 0.004 * 311 = 4.4
  // units (the size the bed's diagonal alone would give).
  using Alloc = vcg::tri::Allocator<CMeshO>;
  CMeshO mesh;
  const float p[9][3] = {{0, 0, 0},         {220, 0, 0},    {220, 220, 0},
                         {0, 220, 0},       {10, 10, 1},    {12.5f, 10, 1},
                         {12.5f, 12.5f, 1}, {15, 12.5f, 1}, {15, 15, 1}};
  auto vi = Alloc::AddVertices(mesh, 9);
  for (const auto& q : p)
    (vi++)->P() = CMeshO::CoordType(q[0], q[1], q[2]);
  const int f[4][3] = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {6, 7, 8}};
  auto fi = Alloc::AddFaces(mesh, 4);
  for (const auto& t : f) {
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &mesh.vert[std::size_t(t[k])];
    ++fi;
  }
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  const meshbridge::DefectReport report = meshbridge::detect_defects(soup.soup);
  ASSERT_EQ(report.pinch_vertices.size(), 1u);
  CMeshO layer;
  layer.face.EnableColor();
  mbm::build_defect_tubes(soup, report, layer);
  // Every vertex of the layer that belongs to the bowtie's tubes and marker lies within 0.3 of
  // the shortest bowtie edge (2.5) of the bowtie: x and y in [10 - 0.75, 15 + 0.75].
  std::size_t near_bowtie = 0;
  for (const CVertexO& v : layer.vert) {
    const float x = v.cP()[0], y = v.cP()[1];
    if (x < 5 || y < 5 || x > 100 || y > 100)
      continue;  // the bed's own boundary tubes
    ++near_bowtie;
    EXPECT_GE(x, 10 - 0.76f);
    EXPECT_LE(x, 15 + 0.76f);
    EXPECT_GE(y, 10 - 0.76f);
    EXPECT_LE(y, 15 + 0.76f);
  }
  EXPECT_EQ(near_bowtie, 6u * 12 + 6u);  // six boundary tubes of 12 vertices, one marker
}

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
  EXPECT_EQ(faces_of_color(layer, vcg::Color4b::Red), tube + 8 * markers);
  EXPECT_EQ(faces_of_color(layer, vcg::Color4b::Green), tube * boundary);
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

TEST(FilterCatalog, both_filters_take_weld_tolerance_and_close_t_junctions_with_core_defaults) {
  for (mbm::FilterId id : mbm::all_filters()) {
    const mbm::ParameterSpec* weld = find_parameter(id, "weld_tolerance");
    ASSERT_NE(weld, nullptr);
    EXPECT_EQ(weld->kind, mbm::ParameterSpec::Kind::length);
    EXPECT_EQ(weld->length_default, meshbridge::kAutoWeldTolerance);
    EXPECT_NE(weld->tooltip.find("Negative (the default, -1): automatic"), std::string::npos);
    const mbm::ParameterSpec* t = find_parameter(id, "close_t_junctions");
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->kind, mbm::ParameterSpec::Kind::boolean);
    EXPECT_TRUE(t->bool_default);
  }
}

TEST(FilterCatalog, negative_weld_tolerance_is_automatic_and_zero_is_off) {
  EXPECT_EQ(mbm::close_gaps_options(-1, true).tolerance, meshbridge::kAutoWeldTolerance);
  EXPECT_EQ(mbm::close_gaps_options(-0.25, true).tolerance, meshbridge::kAutoWeldTolerance);
  EXPECT_EQ(mbm::close_gaps_options(0, true).tolerance, 0.0);
  EXPECT_EQ(mbm::close_gaps_options(0.002, false).tolerance, 0.002);
  EXPECT_FALSE(mbm::close_gaps_options(0.002, false).close_t_junctions);
  const mbm::ParameterSpec n = mbm::integer_parameter("fill_holes", 0, "Fill holes", "0 = off");
  EXPECT_EQ(n.kind, mbm::ParameterSpec::Kind::integer);
  EXPECT_EQ(n.int_default, 0);
}

TEST(FilterCatalog, repair_takes_fill_holes_off_by_default_and_detect_does_not) {
  const mbm::ParameterSpec* fill = find_parameter(mbm::FilterId::repair, "fill_holes");
  ASSERT_NE(fill, nullptr);
  EXPECT_EQ(fill->kind, mbm::ParameterSpec::Kind::integer);
  EXPECT_EQ(fill->int_default, 0);
  EXPECT_EQ(find_parameter(mbm::FilterId::detect, "fill_holes"), nullptr);
  EXPECT_EQ(mbm::fill_holes_max_edges(0), 0u);
  EXPECT_EQ(mbm::fill_holes_max_edges(-3), 0u);
  EXPECT_EQ(mbm::fill_holes_max_edges(32), 32u);
}

TEST(FilterActions, is_stl_file_name_by_extension_in_any_case) {
  EXPECT_TRUE(mbm::is_stl_file_name("/tmp/part.stl"));
  EXPECT_TRUE(mbm::is_stl_file_name("PART.STL"));
  EXPECT_FALSE(mbm::is_stl_file_name("part.stl.ply"));
  EXPECT_FALSE(mbm::is_stl_file_name("stl"));
  EXPECT_FALSE(mbm::is_stl_file_name(""));
}

TEST(FilterActions, repair_logs_what_an_stl_save_reads_back) {
  // The rib is separated from the plate: the 2 vertices of the joint edge are split, and an STL
  // file welds the copies back into the T-junction.
  CMeshO mesh;
  t_junction(mesh);
  FakeHost host("");  // not from a file: split vertices alone ask for the STL line
  const mbm::RepairOutcome out = mbm::repair_singular_defects(mesh, "rib", {}, host);
  EXPECT_EQ(out.report.vertices_split, 2u);
  ASSERT_TRUE(out.reread.has_value());
  EXPECT_EQ(out.reread->singular_edges.size(), 1u);
  EXPECT_EQ(out.reread->num_singular_vertices(), 2u);
  EXPECT_TRUE(has_line(out.log,
                       "STL re-read: saved as STL and loaded again, this layer has singular edges "
                       "1, singular vertices 2, watertight no. STL stores no shared vertices: "
                       "every reader welds the 2 split vertex copies together again"))
      << out.log;
  EXPECT_TRUE(has_line(out.log,
                       "To keep the repair, save as PLY, OBJ or OFF: they keep the 2 split "
                       "vertex copies apart"))
      << out.log;
}

TEST(FilterActions, repair_of_an_stl_layer_without_split_reports_its_reread_too) {
  CMeshO mesh;  // the plate alone (the rib deleted): nothing to split
  t_junction(mesh);
  vcg::tri::Allocator<CMeshO>::DeleteFace(mesh, mesh.face[2]);
  FakeHost stl("/data/plate.STL");
  const mbm::RepairOutcome out = mbm::repair_singular_defects(mesh, "plate.STL", {}, stl);
  EXPECT_EQ(out.report.vertices_split, 0u);
  ASSERT_TRUE(out.reread.has_value());
  EXPECT_TRUE(has_line(out.log,
                       "STL re-read: saved as STL and loaded again, this layer has singular edges "
                       "0, singular vertices 0, watertight no"))
      << out.log;
  EXPECT_EQ(out.log.find("To keep the repair"), std::string::npos) << out.log;

  CMeshO again;  // the same from an OFF file: no STL line at all
  t_junction(again);
  vcg::tri::Allocator<CMeshO>::DeleteFace(again, again.face[2]);
  FakeHost off("/data/plate.off");
  const mbm::RepairOutcome quiet = mbm::repair_singular_defects(again, "plate.off", {}, off);
  EXPECT_FALSE(quiet.reread.has_value());
  EXPECT_EQ(quiet.log.find("STL re-read"), std::string::npos) << quiet.log;
}

TEST(FilterActions, detect_reports_what_gap_closing_would_do_and_moves_nothing) {
  // The plate's two triangles; the second one has its own copy of corner 0, 1e-7 away (a crack
  // the automatic tolerance, 2^-21 of 1, covers). Vertex 5 is an isolated copy of vertex 2 at
  // exactly its position: not a boundary vertex, never welded.
  CMeshO mesh;
  using Alloc = vcg::tri::Allocator<CMeshO>;
  const float p[6][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1e-7f, 0, 0}, {1, 1, 0}};
  auto vi = Alloc::AddVertices(mesh, 6);
  for (const auto& q : p)
    (vi++)->P() = CMeshO::CoordType(q[0], q[1], q[2]);
  auto fi = Alloc::AddFaces(mesh, 2);
  const int f[2][3] = {{0, 1, 2}, {4, 2, 3}};
  for (const auto& t : f) {
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &mesh.vert[std::size_t(t[k])];
    ++fi;
  }
  FakeHost host("");
  mbm::DetectOptions options;
  const mbm::DetectOutcome out = mbm::detect_singular_defects(mesh, "plate", options, host);
  EXPECT_EQ(out.gaps.vertices_welded, 1u);
  EXPECT_EQ(out.gaps.t_junctions_closed, 0u);
  EXPECT_EQ(mesh.vn, 6);
  EXPECT_EQ(mesh.vert[4].P()[0], 1e-7f);
  options.close_gaps.tolerance = 0;
  const mbm::DetectOutcome off = mbm::detect_singular_defects(mesh, "plate", options, host);
  EXPECT_TRUE(has_line(off.log, "gaps: not closed (weld tolerance 0)")) << off.log;
}

TEST(WriteRepaired, faces_added_by_hole_filling_come_last_with_default_attributes) {
  CMeshO mesh;
  open_box(mesh);
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  meshbridge::RepairOptions options;
  options.fill_holes.max_edges = 32;
  const meshbridge::RepairResult result = meshbridge::repair(soup.soup, options);
  ASSERT_EQ(result.report.holes.faces_added, 2u);
  mbm::WriteBackOptions write_options;
  write_options.recompute_normals = false;
  const mbm::WriteBackReport written =
      mbm::write_repaired(mesh, soup, result.mesh, {}, write_options);
  EXPECT_EQ(written.faces_added, 2u);
  EXPECT_EQ(written.faces_out, 12u);
  ASSERT_EQ(mesh.fn, 12);
  for (int f = 0; f < 10; ++f)
    EXPECT_EQ(mesh.face[std::size_t(f)].cC(),
              vcg::Color4b(static_cast<unsigned char>(10 * f), 0, 0, 255));
  for (std::size_t f = 10; f < 12; ++f) {
    const CFaceO& added = mesh.face[f];
    EXPECT_EQ(added.cC(), vcg::Color4b(0, 0, 0, 255)) << f;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(added.cV(k)->cP().Z(), 1.0f) << f;  // they close the top
      EXPECT_EQ(added.cWT(k).U(), float(added.cV(k) - &mesh.vert[0]) / 10) << f;
    }
    EXPECT_NEAR(added.cN().Z(), 1.0f, 1e-6f) << "outward normal of face " << f;
  }
  // Corner origins that claim an input corner on an added face are refused, mesh untouched.
  meshbridge::IndexedMesh wrong = result.mesh;
  wrong.corner_origin.back() = 0;
  CMeshO other;
  open_box(other);
  const mbm::CMeshSoup other_soup = mbm::soup_from_cmesh(other);
  EXPECT_THROW(mbm::write_repaired(other, other_soup, wrong, {}), std::invalid_argument);
  EXPECT_EQ(other.fn, 10);
}

TEST(WriteRepaired, a_triangle_with_a_side_split_at_its_midpoint_is_fanned_without_a_flat_one) {
  // A real-world part (tests/data/realworld2) whose repair splits edges at their midpoint: each
  // triangle on such an edge comes back as a polygon with three corners on a line. Fanned from an
  // end of the split side it gave a zero-area triangle and the split edge again (a singular edge
  // in MeshLab's mesh that the filter did not report).
  const meshbridge::Soup file = meshbridge::read_soup(
      std::string(MESHBRIDGE_SOURCE_DIR) + "/tests/data/realworld2/ur_ur20_forearm_collision.stl");
  CMeshO mesh;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(mesh, file.num_vertices());
  for (const meshbridge::Point& p : file.positions)
    (vi++)->P() = CMeshO::CoordType(float(p[0]), float(p[1]), float(p[2]));
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(mesh, file.num_faces());
  for (std::size_t f = 0; f < file.num_faces(); ++f, ++fi) {
    const meshbridge::PolygonView poly = file.polygon(f);
    ASSERT_EQ(poly.size(), 3u);
    for (int k = 0; k < 3; ++k)
      fi->V(k) = &mesh.vert[poly[std::size_t(k)]];
  }
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  const meshbridge::RepairResult result = meshbridge::repair(soup.soup, {});
  ASSERT_GT(result.report.edges_split_to_stay_manifold, 0u);
  ASSERT_EQ(result.report.after.singular_edges.size(), 0u);
  const mbm::WriteBackReport written = mbm::write_repaired(mesh, soup, result.mesh, {}, {});
  EXPECT_GT(written.polygons_triangulated, 0u);
  const meshbridge::DefectReport in_meshlab =
      meshbridge::detect_defects(mbm::soup_from_cmesh(mesh).soup);
  EXPECT_EQ(in_meshlab.singular_edges.size(), 0u);
  EXPECT_EQ(in_meshlab.num_singular_vertices(), 0u);
  EXPECT_EQ(in_meshlab.duplicate_faces.size(), 0u);
  EXPECT_EQ(in_meshlab.zero_area_faces.size(), 0u);
}
