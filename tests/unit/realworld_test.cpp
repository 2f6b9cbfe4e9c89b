// SPDX-License-Identifier: GPL-3.0-or-later
// The real-world corpus (tests/data/realworld): eight meshes from public projects. Every file is
// read, detected and repaired; detection counts are pinned exactly; where the independent
// manifest (manifest.tsv) counts the same thing the same way it must agree, and where its
// convention differs the difference is explained in tests/data/realworld/DIFFERENCES.md.
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <dirent.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef MESHBRIDGE_REALWORLD_DIR
#error "define MESHBRIDGE_REALWORLD_DIR as the path of tests/data/realworld"
#endif

using namespace meshbridge;
using meshbridge::test_support::expect_repair_invariants;

namespace {

const std::string kDir = MESHBRIDGE_REALWORLD_DIR;

//! What MeshBridge detects in one file, exactly (MeshBridge's conventions, see defect_report.h).
struct Expected {
  const char* file;
  std::size_t vertices, faces, edges;
  std::size_t singular_edges;
  std::map<Index, std::size_t> contenders;  //!< contenders per singular edge -> edges
  std::size_t singular_edge_vertices, pinch_vertices;
  std::size_t boundary_edges, boundary_loops;
  std::size_t isolated, degenerate, set_aside, zero_area, duplicates, inconsistent;
  std::size_t nonorientable, components;
  long long euler;
  bool watertight;
};

void PrintTo(const Expected& e, std::ostream* os) {
  *os << e.file;
}

// clang-format off
const std::vector<Expected> kExpected = {
  // file                                     V      F      E       sing.e  contenders                      s.e.v pinch bnd.e loops iso deg exc zero dup  inc  nonor comp euler  watertight
  {"chair_model.obj",                         3186,  12756, 9554,   9545, {{4, 9517}, {6, 21}, {8, 7}}, 3186, 0,    0,    0,    0,  0,  0,  0,   6382, 0,  0,    4,   6388,  false},
  {"manifold_openscad-nonmanifold-crash.obj", 717,   1442,  2163,   0,    {},                           0,    0,    0,    0,    0,  0,  0,  1,   0,    0,  0,    2,   -4,    true},
  {"trimesh_bunny.ply",                       8171,  16301, 24363,  150,  {{3, 2}, {4, 147}, {6, 1}},   224,  0,    123,  5,    25, 0,  0,  0,   87,   0,  0,    1,   84,    false},
  {"trimesh_cycloidal.ply",                   21384, 43368, 64810,  242,  {{4, 242}},                   244,  26,   0,    0,    0,  0,  0,  0,   0,    0,  0,    112, -58,   false},
  {"admesh_hourglass.stl",                    1075,  2146,  3219,   0,    {},                           0,    0,    0,    0,    0,  0,  0,  0,   0,    72, 0,    1,   2,     false},
  {"thingi10k_908460.stl",                    18035, 36074, 54111,  0,    {},                           0,    0,    0,    0,    0,  0,  0,  0,   0,    0,  0,    1,   -2,    true},
  {"thingi10k_99865.stl",                     35987, 71974, 107961, 0,    {},                           0,    0,    0,    0,    0,  0,  0,  0,   0,    0,  0,    4,   0,     true},
  {"trimesh_angle_block.STL",                 398,   704,   1139,   0,    {},                           0,    33,   166,  4,    0,  0,  0,  0,   0,    0,  0,    1,   -37,   false},
};
// clang-format on

//! One row of manifest.tsv, by column name.
using ManifestRow = std::map<std::string, std::string>;

std::map<std::string, ManifestRow> read_manifest() {
  std::ifstream in(kDir + "/manifest.tsv");
  std::map<std::string, ManifestRow> rows;
  std::string line;
  std::vector<std::string> header;
  const auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::istringstream stream(text);
    std::string field;
    while (std::getline(stream, field, '\t'))
      fields.push_back(field);
    return fields;
  };
  if (std::getline(in, line))
    header = split(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    if (fields.empty())
      continue;
    ManifestRow row;
    for (std::size_t i = 0; i < fields.size() && i < header.size(); ++i)
      row[header[i]] = fields[i];
    rows[fields[0]] = row;
  }
  return rows;
}

std::size_t number(const ManifestRow& row, const std::string& column) {
  const auto it = row.find(column);
  EXPECT_NE(it, row.end()) << "manifest has no column " << column;
  return it == row.end() ? 0 : std::stoull(it->second);
}

//! "4:9517,6:21,8:7" -> {4: 9517, 6: 21, 8: 7}; "-" -> {}.
std::map<Index, std::size_t> valence_histogram(const std::string& text) {
  std::map<Index, std::size_t> histogram;
  if (text == "-")
    return histogram;
  std::istringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto colon = item.find(':');
    histogram[static_cast<Index>(std::stoul(item.substr(0, colon)))] =
        std::stoull(item.substr(colon + 1));
  }
  return histogram;
}

std::map<Index, std::size_t> contender_histogram(const DefectReport& report) {
  std::map<Index, std::size_t> histogram;
  for (const SingularEdge& edge : report.singular_edges)
    ++histogram[edge.contenders];
  return histogram;
}

//! Components of `soup` that have no boundary edge (faces joined through shared edges).
std::set<Index> closed_components(const Soup& soup, const DefectReport& report) {
  const std::vector<Index> label = test_support::face_components(soup);
  std::set<Index> closed(label.begin(), label.end());
  std::map<std::pair<Index, Index>, Index> edge_face;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Index a = p[i], b = p[(i + 1) % p.size()];
      edge_face[{std::min(a, b), std::max(a, b)}] = static_cast<Index>(f);
    }
  }
  for (const VertexPair& edge : report.boundary_edges)
    closed.erase(label[edge_face.at({edge.v0, edge.v1})]);
  return closed;
}

class RealWorld : public ::testing::TestWithParam<Expected> {};

std::string test_name(const ::testing::TestParamInfo<Expected>& info) {
  std::string name = info.param.file;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch)))
      ch = '_';
  }
  return name;
}

}  // namespace

TEST(RealWorldCorpus, every_mesh_in_the_directory_has_expectations_and_a_manifest_row) {
  const auto manifest = read_manifest();
  EXPECT_EQ(manifest.size(), kExpected.size());
  std::set<std::string> expected;
  for (const Expected& e : kExpected) {
    expected.insert(e.file);
    EXPECT_EQ(manifest.count(e.file), 1u) << e.file;
  }
  std::set<std::string> present;
  DIR* dir = opendir(kDir.c_str());
  ASSERT_NE(dir, nullptr) << kDir;
  while (const dirent* entry = readdir(dir)) {
    if (is_supported_mesh_file(entry->d_name))
      present.insert(entry->d_name);
  }
  closedir(dir);
  EXPECT_EQ(present, expected);
}

TEST(RealWorldCorpus, licenses_are_recorded_for_every_file) {
  std::ifstream in(kDir + "/LICENSES.md");
  ASSERT_TRUE(in) << "tests/data/realworld/LICENSES.md is missing";
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Expected& e : kExpected)
    EXPECT_NE(text.find(e.file), std::string::npos) << e.file << " has no license entry";
}

TEST_P(RealWorld, detection_counts_are_exact) {
  const Expected& e = GetParam();
  ReadInfo info;
  const Soup soup = read_soup(kDir + "/" + e.file, &info);
  const DefectReport r = detect_defects(soup);
  EXPECT_EQ(r.num_vertices, e.vertices);
  EXPECT_EQ(r.num_faces, e.faces);
  EXPECT_EQ(r.num_edges, e.edges);
  EXPECT_EQ(r.singular_edges.size(), e.singular_edges);
  EXPECT_EQ(contender_histogram(r), e.contenders);
  EXPECT_EQ(r.singular_edge_vertices.size(), e.singular_edge_vertices);
  EXPECT_EQ(r.pinch_vertices.size(), e.pinch_vertices);
  EXPECT_EQ(r.boundary_edges.size(), e.boundary_edges);
  EXPECT_EQ(r.num_boundary_loops, e.boundary_loops);
  EXPECT_EQ(r.isolated_vertices.size(), e.isolated);
  EXPECT_EQ(r.degenerate_faces.size(), e.degenerate);
  EXPECT_EQ(r.faces_set_aside.size(), e.set_aside);
  EXPECT_EQ(r.zero_area_faces.size(), e.zero_area);
  EXPECT_EQ(r.duplicate_faces.size(), e.duplicates);
  EXPECT_EQ(r.inconsistent_edges.size(), e.inconsistent);
  EXPECT_EQ(r.num_nonorientable_components, e.nonorientable);
  EXPECT_EQ(r.num_components, e.components);
  EXPECT_EQ(r.euler_characteristic, e.euler);
  EXPECT_EQ(r.watertight, e.watertight);
}

// Columns where the manifest counts what MeshBridge counts, by the same definition.
TEST_P(RealWorld, agrees_with_the_manifest_where_conventions_agree) {
  const Expected& e = GetParam();
  const auto manifest = read_manifest();
  ASSERT_EQ(manifest.count(e.file), 1u);
  const ManifestRow& row = manifest.at(e.file);
  const Soup soup = read_soup(kDir + "/" + e.file);
  const DefectReport r = detect_defects(soup);
  std::size_t non_triangles = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    non_triangles += soup.arity(f) != 3;
  EXPECT_EQ(r.num_vertices, number(row, "vertices"));
  EXPECT_EQ(r.num_faces, number(row, "faces"));
  EXPECT_EQ(r.singular_edges.size(), number(row, "singular_edges"));
  EXPECT_EQ(contender_histogram(r), valence_histogram(row.at("sing_edge_valence(k:count)")));
  EXPECT_EQ(r.pinch_vertices.size(), number(row, "sing_v_not_on_sing_edge"));
  EXPECT_EQ(r.boundary_edges.size(), number(row, "boundary_edges"));
  EXPECT_EQ(r.inconsistent_edges.size(), number(row, "orientation_flips"));
  EXPECT_EQ(r.degenerate_faces.size(), number(row, "degenerate_faces"));
  EXPECT_EQ(r.duplicate_faces.size(), number(row, "duplicate_faces"));
  EXPECT_EQ(r.isolated_vertices.size(), number(row, "isolated_vertices"));
  EXPECT_EQ(non_triangles, number(row, "non_tri_faces"));
  // The manifest's singular vertices are pinch vertices only (its fans join through singular
  // edges too), and its components join through shared vertices: both are at most ours.
  EXPECT_LE(number(row, "singular_vertices"), r.num_singular_vertices());
  EXPECT_LE(number(row, "components"), r.num_components);
}

TEST_P(RealWorld, repair_keeps_every_invariant_and_converges) {
  const Expected& e = GetParam();
  const Soup soup = read_soup(kDir + "/" + e.file);
  const DefectReport before = detect_defects(soup);
  const RepairResult once = repair(soup);
  expect_repair_invariants(soup, once);
  const RepairReport& r = once.report;
  EXPECT_EQ(r.faces_in, e.faces);
  EXPECT_EQ(r.faces_set_aside, 0u);  // no polygon in the corpus has < 3 distinct corners
  EXPECT_EQ(r.faces_out, e.faces);
  EXPECT_EQ(r.vertices_out, e.vertices + r.vertices_split - r.gaps.vertices_welded);
  EXPECT_EQ(r.before.singular_edges.size(), before.singular_edges.size());
  EXPECT_EQ(r.before.num_singular_vertices(), before.num_singular_vertices());
  EXPECT_EQ(r.components_before, before.num_components);
  EXPECT_EQ(r.boundary_edges_before, before.boundary_edges.size());
  EXPECT_EQ(r.after.num_faces, e.faces);
  EXPECT_EQ(r.after.num_nonorientable_components, 0u);
  EXPECT_EQ(r.boundary_edges_after, r.after.boundary_edges.size());
  EXPECT_EQ(r.components_after, r.after.num_components);
  // Isolated vertices stay isolated (cleanup is off), and no other vertex becomes isolated.
  EXPECT_EQ(r.after.isolated_vertices.size(), e.isolated);

  // Every closed component of the result is oriented by its nesting: outward, unless it lies
  // inside another closed component (a cavity: the winding number of that component is 1 at
  // the centroids of 8 of its faces). No volume: faces glued back to back, whose sign is
  // rounding noise, may go either way.
  const std::set<Index> closed = closed_components(once.mesh.soup, r.after);
  const std::vector<Index> label = test_support::face_components(once.mesh.soup);
  std::size_t cavities = 0;
  for (Index c : closed) {
    const double volume = test_support::signed_volume(once.mesh.soup, label, c);
    if (volume >= -1e-9 * test_support::volume_magnitude(once.mesh.soup, label, c))
      continue;
    bool nested = false;
    for (Index d : closed)
      nested = nested || (d != c && test_support::lies_inside(once.mesh.soup, label, c, d));
    EXPECT_TRUE(nested) << "component " << c << " has volume " << volume;
    ++cavities;
  }
  EXPECT_EQ(cavities, e.file == "chair_model.obj" ? 1u : 0u);  // DIFFERENCES.md

  // Idempotence: repairing the output changes nothing.
  const RepairResult twice = repair(once.mesh.soup);
  expect_repair_invariants(once.mesh.soup, twice);
  EXPECT_EQ(twice.mesh.soup.positions, once.mesh.soup.positions);
  EXPECT_EQ(twice.mesh.soup.corner_vertices, once.mesh.soup.corner_vertices);
  EXPECT_EQ(twice.mesh.soup.face_begin, once.mesh.soup.face_begin);
  EXPECT_EQ(twice.report.vertices_split, 0u);
  EXPECT_EQ(twice.report.faces_flipped, 0u);
  EXPECT_EQ(twice.report.sides_cut, 0u);
  EXPECT_EQ(twice.report.sides_cut_for_orientation, 0u);
  EXPECT_EQ(twice.report.sides_stitched, 0u);
  EXPECT_EQ(twice.report.components_after, r.components_after);
  EXPECT_EQ(twice.report.boundary_edges_after, r.boundary_edges_after);
}

TEST(RealWorldCorpus, clean_inputs_are_left_exactly_as_they_are) {
  std::size_t clean = 0;
  for (const Expected& e : kExpected) {
    if (e.singular_edges + e.singular_edge_vertices + e.pinch_vertices + e.inconsistent != 0)
      continue;
    SCOPED_TRACE(e.file);
    ++clean;
    const Soup soup = read_soup(kDir + "/" + e.file);
    const RepairResult r = repair(soup);
    EXPECT_EQ(r.mesh.soup.positions, soup.positions);
    EXPECT_EQ(r.mesh.soup.corner_vertices, soup.corner_vertices);
    EXPECT_EQ(r.report.faces_flipped, 0u);
    EXPECT_EQ(r.report.components_after, e.components);
  }
  EXPECT_EQ(clean, 3u);  // the openscad model and the two Thingi10K models
}

TEST_P(RealWorld, repaired_file_reads_back_manifold) {
  const Expected& e = GetParam();
  const Soup soup = read_soup(kDir + "/" + e.file);
  const RepairResult r = repair(soup);
  char dir_template[] = "/tmp/meshbridge_realworld_XXXXXX";
  ASSERT_NE(mkdtemp(dir_template), nullptr);
  const std::string path = std::string(dir_template) + "/repaired.ply";
  write_mesh(path, r.mesh);
  const Soup back = read_soup(path);
  std::remove(path.c_str());
  rmdir(dir_template);
  EXPECT_EQ(back.num_faces(), e.faces);
  EXPECT_EQ(back.num_vertices(), r.mesh.soup.num_vertices());
  EXPECT_EQ(back.corner_vertices, r.mesh.soup.corner_vertices);
  const DefectReport after = detect_defects(back);
  EXPECT_TRUE(after.singular_edges.empty());
  EXPECT_EQ(after.num_singular_vertices(), 0u);
  EXPECT_TRUE(after.inconsistent_edges.empty());
}

INSTANTIATE_TEST_SUITE_P(Corpus, RealWorld, ::testing::ValuesIn(kExpected), test_name);

TEST_P(RealWorld, repair_does_not_depend_on_face_order_or_polygon_start) {
  const Expected& e = GetParam();
  const Soup soup = read_soup(kDir + "/" + e.file);
  const RepairResult reference = repair(soup);
  const DefectReport reference_before = detect_defects(soup);
  for (std::uint32_t seed : {1u, 2u}) {
    SCOPED_TRACE(seed);
    const Soup shuffled = test_support::shuffled(soup, seed);
    const DefectReport before = detect_defects(shuffled);
    EXPECT_EQ(before.singular_edges.size(), reference_before.singular_edges.size());
    EXPECT_EQ(before.num_singular_vertices(), reference_before.num_singular_vertices());
    EXPECT_EQ(before.boundary_edges.size(), reference_before.boundary_edges.size());
    EXPECT_EQ(before.num_components, reference_before.num_components);
    const RepairResult r = repair(shuffled);
    EXPECT_EQ(r.mesh.soup.num_vertices(), reference.mesh.soup.num_vertices());
    EXPECT_EQ(r.report.components_after, reference.report.components_after);
    EXPECT_EQ(r.report.boundary_edges_after, reference.report.boundary_edges_after);
    EXPECT_EQ(r.report.sides_cut, reference.report.sides_cut);
  }
}
