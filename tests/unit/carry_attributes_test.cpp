// SPDX-License-Identifier: GPL-3.0-or-later
// Colours and groups survive a repair: every output element takes its original's attribute.
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <string>

using namespace meshbridge;

namespace {

Rgba color_of(std::size_t i) {
  return {static_cast<std::uint8_t>(10 + i), static_cast<std::uint8_t>(200 - i),
          static_cast<std::uint8_t>(3 * i), 255};
}

}  // namespace

TEST(CarryAttributes, split_vertices_and_faces_keep_their_colors_through_a_ply_file) {
  const Soup soup = models::two_cubes_sharing_edge();
  MeshAttributes attributes;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    attributes.vertex_colors.push_back(color_of(v));
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    attributes.face_colors.push_back(color_of(50 + f));

  const RepairResult result = repair(soup);
  ASSERT_EQ(result.mesh.soup.num_vertices(), 16u);  // the two shared vertices split
  const MeshAttributes carried = carry_attributes(attributes, result.mesh);
  ASSERT_EQ(carried.vertex_colors.size(), 16u);
  ASSERT_EQ(carried.face_colors.size(), result.mesh.soup.num_faces());

  char name[] = "/tmp/meshbridge_carry_XXXXXX.ply";
  const int fd = mkstemps(name, 4);
  ASSERT_GE(fd, 0);
  close(fd);
  write_mesh(name, result.mesh, &attributes);  // the input's: write_mesh maps them itself
  MeshAttributes back;
  const Soup reread = read_soup(name, nullptr, &back);
  std::remove(name);
  ASSERT_EQ(reread.num_vertices(), 16u);
  ASSERT_EQ(back.vertex_colors.size(), 16u);
  for (std::size_t v = 0; v < 16; ++v)
    EXPECT_EQ(back.vertex_colors[v], color_of(result.mesh.vertex_origin[v])) << "vertex " << v;
  ASSERT_EQ(back.face_colors.size(), reread.num_faces());
  for (std::size_t f = 0; f < reread.num_faces(); ++f)
    EXPECT_EQ(back.face_colors[f], color_of(50 + result.mesh.face_origin[f])) << "face " << f;
}

TEST(CarryAttributes, groups_move_with_their_faces_and_emptied_ones_give_way) {
  IndexedMesh mesh;
  mesh.face_origin = {0, 1, 1, 3, 4};  // face 1 split in two, face 2 set aside
  MeshAttributes input;
  input.face_groups = {{"g a", 0}, {"g b", 2}, {"g c", 3}, {"g d", 5}};
  const MeshAttributes out = carry_attributes(input, mesh);
  ASSERT_EQ(out.face_groups.size(), 3u);
  EXPECT_EQ(out.face_groups[0].name, "g a");
  EXPECT_EQ(out.face_groups[0].first_face, 0u);
  EXPECT_EQ(out.face_groups[1].name, "g c");  // "g b" held only the set-aside face
  EXPECT_EQ(out.face_groups[1].first_face, 3u);
  EXPECT_EQ(out.face_groups[2].name, "g d");  // as in the input: after the last face
  EXPECT_EQ(out.face_groups[2].first_face, 5u);
}

// write_mesh maps the input's colours through the origins once: a set-aside face shifts every
// origin by one, and handing it carry_attributes' output (already mapped) broke this.
TEST(CarryAttributes, write_mesh_maps_input_colors_once_past_a_set_aside_face) {
  Soup soup;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)})
    soup.add_vertex(p);
  soup.add_polygon({0, 0, 1});  // fewer than 3 distinct corners: set aside
  soup.add_polygon({0, 1, 2});
  soup.add_polygon({0, 3, 1});
  MeshAttributes attributes;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    attributes.face_colors.push_back(color_of(f));
  const RepairResult result = repair(soup);
  ASSERT_EQ(result.mesh.face_origin, (std::vector<Index>{1, 2}));

  char name[] = "/tmp/meshbridge_carry_XXXXXX.off";
  const int fd = mkstemps(name, 4);
  ASSERT_GE(fd, 0);
  close(fd);
  write_mesh(name, result.mesh, &attributes);
  MeshAttributes back;
  read_soup(name, nullptr, &back);
  std::remove(name);
  ASSERT_EQ(back.face_colors.size(), 2u);
  EXPECT_EQ(back.face_colors[0], color_of(1));
  EXPECT_EQ(back.face_colors[1], color_of(2));
}
