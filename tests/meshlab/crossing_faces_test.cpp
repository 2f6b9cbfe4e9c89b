// SPDX-License-Identifier: GPL-3.0-or-later
// Detect's self-intersections on CMeshO, without MeshLab running: the violet faces of the defect
// layer (crossing_faces.h), the log lines, the returned counts, and the parameter whose default
// depends on the mesh's size.
#include "crossing_faces.h"
#include "cmesh_adapter.h"
#include "fake_host.h"
#include "filter_actions.h"
#include "filter_catalog.h"

#include <vcg/complex/allocate.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace mbm = meshbridge::meshlab;

namespace {

//! Two unit cubes, 12 outward triangles each, no shared vertex; the second moved by `shift`.
void two_cubes(CMeshO& m, const vcg::Point3f& shift) {
  using Alloc = vcg::tri::Allocator<CMeshO>;
  auto vi = Alloc::AddVertices(m, 16);
  for (int c = 0; c < 16; ++c) {
    const vcg::Point3f corner(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1));
    (vi++)->P() = c < 8 ? corner : corner + shift;
  }
  const int quads[6][4] = {{0, 4, 6, 2}, {0, 1, 5, 4}, {0, 2, 3, 1},
                           {1, 3, 7, 5}, {2, 6, 7, 3}, {4, 5, 7, 6}};
  auto fi = Alloc::AddFaces(m, 24);
  for (int cube = 0; cube < 2; ++cube) {
    for (const auto& q : quads) {
      const int triangles[2][3] = {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}};
      for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k)
          fi->V(k) = &m.vert[std::size_t(8 * cube + t[k])];
        ++fi;
      }
    }
  }
}

std::size_t faces_of_color(const CMeshO& m, vcg::Color4b c) {
  std::size_t n = 0;
  for (const CFaceO& f : m.face)
    n += (!f.IsD() && f.cC() == c) ? 1 : 0;
  return n;
}

std::map<std::string, long long> count_map(const mbm::DetectOutcome& out) {
  std::map<std::string, long long> counts;
  for (const mbm::FilterCount& c : out.counts)
    counts[c.name] = c.value;
  return counts;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

//! A parameter list as MeshLab's, with only some parameters set.
struct Parameters {
  std::map<std::string, bool> booleans;
  bool hasParameter(const std::string& name) const {
    return booleans.count(name) != 0 || name == mbm::parameter::defect_layer;
  }
  bool getBool(const std::string& name) const {
    const auto it = booleans.find(name);
    return it != booleans.end() && it->second;
  }
  int getEnum(const std::string&) const { return 0; }
  float getAbsPerc(const std::string&) const { return -1; }
};

}  // namespace

TEST(CrossingFaces, crossing_cubes_are_violet_counted_and_returned) {
  CMeshO mesh;
  two_cubes(mesh, vcg::Point3f(0.5f, 0.5f, 0.5f));
  FakeHost host("");
  const mbm::DetectOutcome out = mbm::detect_singular_defects(mesh, "cubes", {}, host);
  ASSERT_TRUE(out.crossings.has_value());
  // Each of the three faces of one cube at its far corner is crossed by the three of the other
  // cube at its near corner, as triangles: the counts `check --self-intersections` gives on the
  // same 24 triangles.
  EXPECT_EQ(out.crossings->face_pairs.size(), 18u);
  EXPECT_EQ(out.crossings->faces.size(), 12u);
  EXPECT_EQ(out.crossings->component_pairs.size(), 1u);
  EXPECT_EQ(out.violet_faces, 12u);
  // Two lifted copies per face, violet per face and per vertex; nothing else in the layer.
  EXPECT_EQ(host.layer().fn, 24);
  EXPECT_EQ(faces_of_color(host.layer(), mbm::kCrossingFaceColor), 24u);
  for (const CVertexO& v : host.layer().vert)
    EXPECT_EQ(v.cC(), mbm::kCrossingFaceColor);
  const auto counts = count_map(out);
  EXPECT_EQ(counts.at("self_intersections.face_pairs"), 18);
  EXPECT_EQ(counts.at("self_intersections.faces"), 12);
  EXPECT_EQ(counts.at("self_intersections.component_pairs"), 1);
  EXPECT_EQ(counts.at("violet_faces"), 12);
  EXPECT_EQ(counts.at("red_edges"), 0);
  EXPECT_EQ(counts.at("green_edges"), 0);
  EXPECT_TRUE(contains(out.log, "self-intersecting face pairs: 18"));
  EXPECT_TRUE(contains(out.log, "pairs of components (shells) crossing: 1  [0-1]"));
  EXPECT_TRUE(contains(out.log,
                       "Defect layer 'cubes - defects': 0 red (singular) edges, 0 green "
                       "(boundary) edges, 0 singular vertex markers, 12 violet "
                       "(self-intersecting) faces"));
  // The mesh itself is untouched: no colour, the same faces.
  EXPECT_EQ(mesh.fn, 24);
  EXPECT_FALSE(mesh.face.IsColorEnabled());
}

TEST(CrossingFaces, copies_lie_off_both_sides_of_their_face) {
  // The -x side of the moved cube lies in the plane x = 0.5; its copies at 0.5 +- 0.001 x the
  // diagonal (sqrt(3 * 1.5^2) = 2.598), the front one wound like the face.
  CMeshO mesh;
  two_cubes(mesh, vcg::Point3f(0.5f, 0.5f, 0.5f));
  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(mesh);
  meshbridge::SelfIntersectionReport crossings;
  crossings.faces = {12};  // triangle 0 of the moved cube's side {0, 4, 6, 2}: x = 0.5, normal -x
  CMeshO layer;
  layer.face.EnableColor();
  EXPECT_EQ(mbm::add_crossing_faces(soup, crossings, layer), 1u);
  ASSERT_EQ(layer.fn, 2);
  const double lift = mbm::kCrossingFaceLift * std::sqrt(3 * 1.5 * 1.5);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(layer.face[0].cV(k)->cP()[0], 0.5 - lift, 1e-6);
    EXPECT_NEAR(layer.face[1].cV(k)->cP()[0], 0.5 + lift, 1e-6);
  }
  EXPECT_LT(layer.face[0].cN()[0], 0);  // facing away from the face, on either side
  EXPECT_GT(layer.face[1].cN()[0], 0);
  crossings.faces = {24};
  EXPECT_THROW(mbm::add_crossing_faces(soup, crossings, layer), std::invalid_argument);
  EXPECT_EQ(layer.fn, 2);
}

TEST(CrossingFaces, touching_cubes_show_no_violet) {
  // Two cubes sharing an edge by position (x = y = 1), as the bundled twocubes and its repair.
  CMeshO mesh;
  two_cubes(mesh, vcg::Point3f(1, 1, 0));
  FakeHost host("");
  const mbm::DetectOutcome out = mbm::detect_singular_defects(mesh, "touching", {}, host);
  ASSERT_TRUE(out.crossings.has_value());
  EXPECT_EQ(out.crossings->face_pairs.size(), 0u);
  EXPECT_EQ(out.violet_faces, 0u);
  EXPECT_EQ(host.layer().fn, 0);
  EXPECT_EQ(count_map(out).at("self_intersections.face_pairs"), 0);
  EXPECT_TRUE(contains(out.log, "self-intersecting face pairs: 0"));
}

TEST(CrossingFaces, turned_off_nothing_is_searched_counted_or_drawn) {
  CMeshO mesh;
  two_cubes(mesh, vcg::Point3f(0.5f, 0.5f, 0.5f));
  FakeHost host("");
  mbm::DetectOptions options;
  options.self_intersections = false;
  const mbm::DetectOutcome out = mbm::detect_singular_defects(mesh, "cubes", options, host);
  EXPECT_FALSE(out.crossings.has_value());
  EXPECT_EQ(host.layer().fn, 0);
  EXPECT_EQ(count_map(out).count("self_intersections.face_pairs"), 0u);
  EXPECT_EQ(count_map(out).count("violet_faces"), 0u);
  EXPECT_TRUE(contains(out.log,
                       "self-intersections: not searched (turn on 'Find "
                       "self-intersections')"));
  EXPECT_FALSE(contains(out.log, "violet"));
}

TEST(CrossingFaces, edge_layer_draws_no_faces_but_counts) {
  CMeshO mesh;
  two_cubes(mesh, vcg::Point3f(0.5f, 0.5f, 0.5f));
  FakeHost host("");
  mbm::DetectOptions options;
  options.layer_form = mbm::DefectLayerForm::edges;
  const mbm::DetectOutcome out = mbm::detect_singular_defects(mesh, "cubes", options, host);
  EXPECT_EQ(host.layer().fn, 0);
  EXPECT_EQ(count_map(out).at("self_intersections.faces"), 12);
  EXPECT_EQ(count_map(out).at("violet_faces"), 0);
  EXPECT_TRUE(contains(out.log,
                       "0 singular vertex markers; the 12 self-intersecting faces are "
                       "not drawn in an Edges layer"));
}

TEST(FilterCatalog, find_self_intersections_is_on_by_default_up_to_two_million_faces) {
  EXPECT_EQ(mbm::kSelfIntersectionsDefaultMaxFaces, 2000000u);
  const auto self_intersections = [](std::size_t faces) -> const mbm::ParameterSpec {
    for (const mbm::ParameterSpec& p : mbm::parameters(mbm::FilterId::detect, faces)) {
      if (std::string(p.name) == "self_intersections")
        return p;
    }
    ADD_FAILURE() << "Detect has no self_intersections parameter";
    return {};
  };
  EXPECT_TRUE(self_intersections(24).bool_default);
  EXPECT_TRUE(self_intersections(2000000).bool_default);
  EXPECT_FALSE(self_intersections(2000001).bool_default);
  EXPECT_EQ(self_intersections(24).kind, mbm::ParameterSpec::Kind::boolean);
  EXPECT_TRUE(contains(self_intersections(24).tooltip, "at most 2000000 faces, off above"));
  EXPECT_TRUE(contains(self_intersections(24).tooltip, "violet"));
  for (const mbm::ParameterSpec& p : mbm::parameters(mbm::FilterId::repair, 24))
    EXPECT_NE(std::string(p.name), "self_intersections");
  // A script that sets it is obeyed; one that predates it gets the size's default.
  Parameters params;
  EXPECT_TRUE(mbm::detect_options(params, 2000000).self_intersections);
  EXPECT_FALSE(mbm::detect_options(params, 2000001).self_intersections);
  params.booleans["self_intersections"] = false;
  EXPECT_FALSE(mbm::detect_options(params, 24).self_intersections);
  params.booleans["self_intersections"] = true;
  EXPECT_TRUE(mbm::detect_options(params, 5000000).self_intersections);
}
