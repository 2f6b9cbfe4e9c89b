// SPDX-License-Identifier: GPL-3.0-or-later
// 3MF keeps shared vertices: a repair survives the file (unlike STL).

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

// Three tetrahedra sharing the edge 0-1, on a printer bed.
Soup three_tetrahedra_on_one_edge() {
  Soup soup;
  soup.add_vertex({150, 150, 150});
  soup.add_vertex({150, 150, 160});
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3, b = a + 0.6;
    const Index p = soup.add_vertex({150 + 10 * std::cos(a), 150 + 10 * std::sin(a), 155});
    const Index q = soup.add_vertex({150 + 10 * std::cos(b), 150 + 10 * std::sin(b), 155});
    soup.add_polygon({0, 1, p});
    soup.add_polygon({0, q, 1});
    soup.add_polygon({0, p, q});
    soup.add_polygon({1, q, p});
  }
  return soup;
}

std::string scratch(const char* name) {
  return "/tmp/meshbridge_3mf_" + std::to_string(::getpid()) + "_" + name;
}

TEST(Format3mf, repaired_split_vertices_survive_the_file) {
  const RepairResult r = repair(three_tetrahedra_on_one_edge());
  ASSERT_EQ(r.mesh.soup.num_vertices(), 12u);
  const std::string path = scratch("tets.3mf");
  write_mesh(path, r.mesh);
  ReadInfo info;
  const Soup back = read_soup(path, &info);
  std::remove(path.c_str());
  EXPECT_EQ(back.num_vertices(), 12u);
  EXPECT_EQ(back.num_faces(), 12u);
  EXPECT_EQ(back.corner_vertices, r.mesh.soup.corner_vertices);
  // 3MF stores float32 as decimal text; lib3mf 1.8's write and read round trip lands within a
  // few float32 units in the last place (measured: up to 1.4 at 160 mm).
  for (std::size_t v = 0; v < back.num_vertices(); ++v)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(back.positions[v][a], r.mesh.soup.positions[v][a],
                  4 * std::ldexp(std::abs(r.mesh.soup.positions[v][a]), -23));
  const DefectReport report = detect_defects(back);
  EXPECT_TRUE(report.singular_edges.empty());
  EXPECT_EQ(report.num_singular_vertices(), 0u);
  EXPECT_EQ(report.num_components, 3u);
  EXPECT_TRUE(report.watertight);
}

// The unit tetrahedron, outward.
void set_tetrahedron(NMR::PLib3MFModelMeshObject* object) {
  NMR::MODELMESHVERTEX v[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  NMR::MODELMESHTRIANGLE t[4] = {{{0, 2, 1}}, {{0, 1, 3}}, {{0, 3, 2}}, {{1, 2, 3}}};
  ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(object, v, 4, t, 4), LIB3MF_OK);
}

// lib3mf's layout: row j gives output coordinate j, column 3 the translation.
NMR::MODELTRANSFORM transform(std::vector<float> rows) {
  NMR::MODELTRANSFORM t{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      t.m_fFields[j][i] = rows[std::size_t(4 * j + i)];
  return t;
}

// A slicer's file: one tetrahedron placed twice (as stored, then turned 90 degrees about z and
// moved by 10 in x), a components object holding it twice (moved up by 5, scaled by 2) placed at
// y = 20, and a tetrahedron no build item uses.
void write_build_with_transforms(const std::string& path) {
  NMR::PLib3MFModel* model = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  NMR::PLib3MFModelMeshObject *tet = nullptr, *unplaced = nullptr;
  NMR::PLib3MFModelComponentsObject* group = nullptr;
  NMR::PLib3MFModelComponent *up = nullptr, *big = nullptr;
  NMR::PLib3MFModelBuildItem *as_stored = nullptr, *turned = nullptr, *grouped = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &tet), LIB3MF_OK);
  set_tetrahedron(tet);
  ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &unplaced), LIB3MF_OK);
  set_tetrahedron(unplaced);
  ASSERT_EQ(NMR::lib3mf_model_addcomponentsobject(model, &group), LIB3MF_OK);
  NMR::MODELTRANSFORM t_up = transform({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 5});
  NMR::MODELTRANSFORM t_big = transform({2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0});
  ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(group, tet, &t_up, &up), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(group, tet, &t_big, &big), LIB3MF_OK);
  NMR::MODELTRANSFORM t_turned = transform({0, -1, 0, 10, 1, 0, 0, 0, 0, 0, 1, 0});
  NMR::MODELTRANSFORM t_grouped = transform({1, 0, 0, 0, 0, 1, 0, 20, 0, 0, 1, 0});
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, tet, nullptr, &as_stored), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, tet, &t_turned, &turned), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, group, &t_grouped, &grouped), LIB3MF_OK);
  NMR::PLib3MFModelWriter* writer = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_querywriter(model, "3mf", &writer), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()), LIB3MF_OK);
  for (NMR::PLib3MFBase* p : std::vector<NMR::PLib3MFBase*>{writer, as_stored, turned, grouped, up,
                                                            big, group, unplaced, tet, model})
    NMR::lib3mf_release(p);
}

TEST(Format3mf, build_items_and_components_place_their_objects_as_a_slicer_does) {
  const std::string path = scratch("build.3mf");
  write_build_with_transforms(path);
  const Soup soup = read_soup(path);
  std::remove(path.c_str());
  // Five tetrahedra: as stored, turned, the group's two, the unplaced one.
  ASSERT_EQ(soup.num_vertices(), 20u);
  ASSERT_EQ(soup.num_faces(), 20u);
  const std::vector<Point> expected = {
      {0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {0, 0, 1},   // as stored
      {10, 0, 0}, {10, 1, 0}, {9, 0, 0},  {10, 0, 1},  // x' = 10 - y, y' = x
      {0, 20, 5}, {1, 20, 5}, {0, 21, 5}, {0, 20, 6},  // component up 5, item at y = 20
      {0, 20, 0}, {2, 20, 0}, {0, 22, 0}, {0, 20, 2},  // component scaled 2, item at y = 20
      {0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {0, 0, 1},   // in no build item: as stored
  };
  for (std::size_t v = 0; v < expected.size(); ++v)
    EXPECT_EQ(soup.positions[v], expected[v]) << "vertex " << v;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    for (Index c : soup.polygon(f))
      EXPECT_EQ(c / 4, f / 4) << "face " << f << " uses another placement's vertex";
  const DefectReport report = detect_defects(soup);
  EXPECT_EQ(report.num_components, 5u);
  EXPECT_TRUE(report.watertight);
}

TEST(Format3mf, a_file_that_is_not_3mf_is_an_error_naming_it) {
  const std::string path = scratch("bad.3mf");
  std::ofstream(path) << "solid not a zip\n";
  try {
    read_soup(path);
    FAIL() << "no error";
  } catch (const ReadError& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("Could not read ZIP file"), std::string::npos)
        << error.what();  // lib3mf's own words, not only its error number
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace meshbridge
