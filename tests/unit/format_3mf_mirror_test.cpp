// SPDX-License-Identifier: GPL-3.0-or-later
// A 3MF placement that mirrors (a build item's or a component's transform with a negative
// determinant) reverses the triangles' winding, as slicers read it: a correct file is read
// outward, with nothing for repair to flip. Two mirrors down the component tree cancel.

#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

std::string scratch(const char* name) {
  return "/tmp/meshbridge_3mf_mirror_" + std::to_string(::getpid()) + "_" + name;
}

// Six times the signed volume enclosed by the triangles of `soup` (positive: outward).
double six_volume(const Soup& soup) {
  double sum = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    const Point& a = soup.positions[p[0]];
    for (std::size_t c = 1; c + 1 < p.size(); ++c) {
      const Point& b = soup.positions[p[c]];
      const Point& d = soup.positions[p[c + 1]];
      sum += a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
             a[2] * (b[0] * d[1] - b[1] * d[0]);
    }
  }
  return sum;
}

NMR::MODELTRANSFORM transform(std::vector<float> rows) {
  NMR::MODELTRANSFORM t{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      t.m_fFields[j][i] = rows[std::size_t(4 * j + i)];
  return t;
}

const NMR::MODELTRANSFORM kMirrorX = transform({-1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0});
const NMR::MODELTRANSFORM kMirrorY = transform({1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 7});

// The unit tetrahedron, outward (six times its volume is 1), placed by one build item: with
// `item` as its transform (or none), through a components object whose one component has
// `component` (or straight, when null).
void write_placed_tetrahedron(const std::string& path, const NMR::MODELTRANSFORM* item,
                              const NMR::MODELTRANSFORM* component, bool through_component) {
  NMR::PLib3MFModel* model = nullptr;
  ASSERT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  std::vector<NMR::PLib3MFBase*> made;
  NMR::PLib3MFModelMeshObject* tet = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addmeshobject(model, &tet), LIB3MF_OK);
  made.push_back(tet);
  NMR::MODELMESHVERTEX v[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  NMR::MODELMESHTRIANGLE t[4] = {{{0, 2, 1}}, {{0, 1, 3}}, {{0, 3, 2}}, {{1, 2, 3}}};
  ASSERT_EQ(NMR::lib3mf_meshobject_setgeometry(tet, v, 4, t, 4), LIB3MF_OK);
  NMR::PLib3MFModelObjectResource* placed = tet;
  if (through_component) {
    NMR::PLib3MFModelComponentsObject* group = nullptr;
    NMR::PLib3MFModelComponent* part = nullptr;
    ASSERT_EQ(NMR::lib3mf_model_addcomponentsobject(model, &group), LIB3MF_OK);
    ASSERT_EQ(NMR::lib3mf_componentsobject_addcomponent(
                  group, tet, const_cast<NMR::MODELTRANSFORM*>(component), &part),
              LIB3MF_OK);
    made.push_back(part);
    made.push_back(group);
    placed = group;
  }
  NMR::PLib3MFModelBuildItem* build_item = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_addbuilditem(model, placed, const_cast<NMR::MODELTRANSFORM*>(item),
                                           &build_item),
            LIB3MF_OK);
  made.push_back(build_item);
  NMR::PLib3MFModelWriter* writer = nullptr;
  ASSERT_EQ(NMR::lib3mf_model_querywriter(model, "3mf", &writer), LIB3MF_OK);
  ASSERT_EQ(NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()), LIB3MF_OK);
  made.push_back(writer);
  made.push_back(model);
  for (NMR::PLib3MFBase* p : made)
    NMR::lib3mf_release(p);
}

// Reads `path` and checks that the tetrahedron comes out outward: six times its volume is +1 as
// read, repair flips nothing, and repair without orientation writes it outward too.
void expect_outward(const std::string& path) {
  const Soup soup = read_soup(path);
  ASSERT_EQ(soup.num_faces(), 4u);
  EXPECT_NEAR(six_volume(soup), 1.0, 1e-6);
  const RepairResult oriented = repair(soup);
  EXPECT_EQ(oriented.report.faces_flipped, 0u);
  RepairOptions no_orient;
  no_orient.orient = false;
  const RepairResult as_read = repair(soup, no_orient);
  const std::string out = path + ".out.3mf";
  write_mesh(out, as_read.mesh);
  EXPECT_NEAR(six_volume(read_soup(out)), 1.0, 1e-6);
  std::remove(out.c_str());
  std::remove(path.c_str());
}

TEST(Format3mfMirror, a_mirroring_build_item_reverses_the_winding) {
  const std::string path = scratch("item.3mf");
  write_placed_tetrahedron(path, &kMirrorX, nullptr, false);
  const Soup soup = read_soup(path);
  EXPECT_EQ(soup.positions[1], Point(4, 0, 0));  // x' = 5 - x
  expect_outward(path);
}

TEST(Format3mfMirror, a_mirroring_component_reverses_the_winding) {
  const std::string path = scratch("component.3mf");
  write_placed_tetrahedron(path, nullptr, &kMirrorY, true);
  const Soup soup = read_soup(path);
  EXPECT_EQ(soup.positions[2], Point(0, -1, 7));  // y' = -y, z' = z + 7
  expect_outward(path);
}

TEST(Format3mfMirror, a_mirroring_item_and_component_cancel) {
  const std::string path = scratch("both.3mf");
  write_placed_tetrahedron(path, &kMirrorX, &kMirrorY, true);
  const Soup soup = read_soup(path);
  EXPECT_EQ(soup.positions[3], Point(5, 0, 8));
  // Two mirrors: a turn; the triangles keep their order.
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  expect_outward(path);
}

TEST(Format3mfMirror, a_component_that_only_moves_keeps_the_winding) {
  const std::string path = scratch("moved.3mf");
  const NMR::MODELTRANSFORM moved = transform({1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0});
  write_placed_tetrahedron(path, &moved, &moved, true);
  const Soup soup = read_soup(path);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  expect_outward(path);
}

}  // namespace
}  // namespace meshbridge
