// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ texture coordinates and normals through a repair (issue 31): the reader keeps the vt/vn
// records of every face corner, repair carries them through the corner origins (the copies of a
// split vertex keep the values of their own faces' corners), a corner repair inserts into a side
// is interpolated between the side's ends, a face hole filling adds has none (and the output
// says so), and the OBJ writer writes them back.

#include "meshbridge/fill_holes.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/repair_file.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

using Record = std::array<double, 3>;

// The six faces of the unit cube, wound outward, as corners in {0, 1}^3, and their normals.
constexpr int kCubeFaces[6][4][3] = {
    {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
    {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
    {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
constexpr int kCubeNormals[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                    {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};

//! An OBJ of unit cubes at `offsets` (vertices at one position shared), every corner with a vt
//! of its own ((4f + k) / 64, 1 - that) and a vn per face direction; the faces listed in `skip`
//! left out.
std::string textured_cubes(const std::vector<std::array<int, 3>>& offsets,
                           const std::vector<int>& skip = {}) {
  std::map<std::array<int, 3>, int> vertex;
  std::ostringstream v, vt, vn, f;
  for (const auto& n : kCubeNormals)
    vn << "vn " << n[0] << ' ' << n[1] << ' ' << n[2] << '\n';
  int face = 0, record = 0;
  for (const auto& o : offsets) {
    for (int side = 0; side < 6; ++side, ++face) {
      if (std::find(skip.begin(), skip.end(), face) != skip.end())
        continue;
      f << 'f';
      for (int k = 0; k < 4; ++k) {
        const std::array<int, 3> p = {o[0] + kCubeFaces[side][k][0], o[1] + kCubeFaces[side][k][1],
                                      o[2] + kCubeFaces[side][k][2]};
        if (vertex.emplace(p, static_cast<int>(vertex.size()) + 1).second)
          v << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        ++record;
        vt << "vt " << record / 64.0 << ' ' << 1 - record / 64.0 << '\n';
        f << ' ' << vertex[p] << '/' << record << '/' << side + 1;
      }
      f << '\n';
    }
  }
  return v.str() + vt.str() + vn.str() + f.str();
}

class ObjCornerAttributes : public test_support::ScratchFolderTest {
 protected:
  ObjCornerAttributes() : ScratchFolderTest("obj_uv") {}

  struct Reading {
    Soup soup;
    MeshAttributes attributes;
  };
  static Reading read(const std::string& file) {
    Reading r;
    r.soup = read_soup(file, nullptr, &r.attributes);
    return r;
  }
  static std::vector<std::string> lines_of(const std::string& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }
  // The vt (slot 0) or vn (slot 1) values of corner c, or none.
  static const Record* value(const MeshAttributes& a, int slot, std::size_t c) {
    const std::vector<Index>& records =
        slot == 0 ? a.corners.corner_texture : a.corners.corner_normal;
    if (c >= records.size() || records[c] == kNoIndex)
      return nullptr;
    return &(slot == 0 ? a.corners.texture_coordinates : a.corners.normals)[records[c]];
  }
  //! Counts the output corners whose vt and vn are those of the input corner they come from; an
  //! inserted corner (its origin repeats a neighbour's) is left to the caller.
  static std::size_t corners_carried(const MeshAttributes& in, const RepairedFile& file,
                                     const MeshAttributes& out) {
    std::size_t same = 0;
    for (std::size_t c = 0; c < file.mesh.soup.num_corners(); ++c) {
      const Index o = file.mesh.corner_origin[c];
      bool equal = true;
      for (int slot = 0; slot < 2; ++slot) {
        const Record* a = value(in, slot, o);
        const Record* b = value(out, slot, c);
        equal = equal && a != nullptr && b != nullptr && *a == *b;
      }
      same += equal;
    }
    return same;
  }
};

TEST_F(ObjCornerAttributes, two_cubes_on_one_edge_keep_every_corners_vt_and_vn) {
  const std::string in = write("two_cubes.obj", textured_cubes({{0, 0, 0}, {1, 1, 0}}));
  const Reading input = read(in);
  ASSERT_EQ(input.soup.num_vertices(), 14u);  // the two cubes share the edge x = y = 1
  ASSERT_EQ(input.attributes.corners.texture_coordinates.size(), 48u);
  ASSERT_EQ(input.attributes.corners.normals.size(), 6u);
  ASSERT_EQ(input.attributes.corners.corner_texture.size(), 48u);
  EXPECT_EQ(input.attributes.corners.corner_texture[47], 47u);
  EXPECT_EQ(input.attributes.corners.corner_normal[47], 5u);
  EXPECT_EQ(input.attributes.corners.texture_components, 2);

  RepairFileOptions options;
  options.keep_meshes = true;
  const std::string out = path("two_cubes_out.obj");
  const RepairedFile file = repair_file(in, out, options);
  EXPECT_EQ(file.report.before.singular_edges.size(), 1u);
  EXPECT_EQ(file.report.vertices_split, 2u);
  EXPECT_EQ(file.report.after.singular_edges.size(), 0u);
  EXPECT_EQ(file.written.left_out, std::vector<std::string>{});  // nothing lost

  const Reading output = read(out);
  ASSERT_EQ(output.soup.num_vertices(), 16u);
  ASSERT_EQ(output.soup.num_corners(), 48u);
  EXPECT_EQ(output.attributes.corners.texture_coordinates.size(), 48u);  // none added
  EXPECT_EQ(output.attributes.corners.normals.size(), 6u);
  EXPECT_EQ(corners_carried(input.attributes, file, output.attributes), 48u);
  // The two vertices of the edge have two copies each, whose corners kept their own faces' vt.
  std::map<Index, int> copies;
  for (Index origin : file.mesh.vertex_origin)
    ++copies[origin];
  EXPECT_EQ(
      std::count_if(copies.begin(), copies.end(), [](const auto& c) { return c.second == 2; }), 2);
  std::size_t faces_with_both = 0;
  for (const std::string& line : lines_of(out))
    faces_with_both += line.rfind("f ", 0) == 0 && std::count(line.begin(), line.end(), '/') == 8;
  EXPECT_EQ(faces_with_both, 12u);
}

TEST_F(ObjCornerAttributes, a_side_split_at_its_midpoint_gets_the_vt_between_its_ends) {
  // A real part whose repair splits sides at their midpoint, as an OBJ whose vt is the corner's
  // (x, y) and whose vn is (0, 0, 1) on every corner: an inserted corner's vt must be its own
  // (x, y) again (interpolated along the side), every other corner's that of its input corner.
  const Soup stl =
      read_soup(std::string(MESHBRIDGE_REALWORLD_DIR) + "2/ur_ur20_forearm_collision.stl");
  std::ostringstream obj;
  obj.precision(17);
  ASSERT_GT(stl.num_faces(), 0u);
  for (const Point& p : stl.positions)
    obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (Index v : stl.corner_vertices)
    obj << "vt " << stl.positions[v][0] << ' ' << stl.positions[v][1] << '\n';
  obj << "vn 0 0 1\n";
  for (std::size_t f = 0; f < stl.num_faces(); ++f) {
    obj << 'f';
    for (Index c = stl.face_begin[f]; c < stl.face_begin[f + 1]; ++c)
      obj << ' ' << stl.corner_vertices[c] + 1 << '/' << c + 1 << "/1";
    obj << '\n';
  }
  const std::string in = write("ur20.obj", obj.str());
  const Reading input = read(in);
  RepairFileOptions options;
  options.keep_meshes = true;
  const std::string out = path("ur20_out.obj");
  const RepairedFile file = repair_file(in, out, options);
  ASSERT_GT(file.report.edges_split_to_stay_manifold, 0u);
  const Reading output = read(out);
  ASSERT_EQ(output.soup.num_corners(), file.mesh.soup.num_corners());
  std::size_t inserted = 0, interpolated = 0;
  const Soup& mesh = file.mesh.soup;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Index first = mesh.face_begin[f], last = mesh.face_begin[f + 1];
    for (Index c = first; c < last; ++c) {
      const Index next = c + 1 < last ? c + 1 : first, before = c > first ? c - 1 : last - 1;
      const Index o = file.mesh.corner_origin[c];
      if (o != file.mesh.corner_origin[next] && o != file.mesh.corner_origin[before])
        continue;
      const Record* uv = value(output.attributes, 0, c);
      const Point& p = mesh.positions[mesh.corner_vertices[c]];
      if (file.mesh.vertex_origin[mesh.corner_vertices[c]] != kNoIndex)
        continue;  // the corner that was there before (a run: it and those inserted after it)
      ++inserted;
      ASSERT_NE(uv, nullptr);
      const double scale = std::max({1.0, std::abs(p[0]), std::abs(p[1])});
      interpolated += std::abs((*uv)[0] - p[0]) <= 1e-12 * scale &&
                      std::abs((*uv)[1] - p[1]) <= 1e-12 * scale &&
                      *value(output.attributes, 1, c) == (Record{0, 0, 1});
    }
  }
  EXPECT_EQ(inserted, 2 * file.report.edges_split_to_stay_manifold);
  EXPECT_EQ(interpolated, inserted);
  // Every corner that is not an inserted one has its input corner's vt and vn.
  EXPECT_EQ(corners_carried(input.attributes, file, output.attributes),
            mesh.num_corners() - inserted);
  // One vt added per midpoint and pair of ends (the two faces of a split pair share it).
  EXPECT_LE(output.attributes.corners.texture_coordinates.size(),
            input.attributes.corners.texture_coordinates.size() + inserted);
  EXPECT_GT(output.attributes.corners.texture_coordinates.size(),
            input.attributes.corners.texture_coordinates.size());
}

TEST_F(ObjCornerAttributes, faces_with_and_without_vt_round_trip_as_they_were) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0.25 0.5 0.75\nvt 1 0\nvt 0 1\nvn 0 0 -1\n"
      "f 1/1 3/3 2/2\nf 1 2 4\nf 1//1 4//1 3//1\nf 2/2/1 3/3/1 4/1/1\n";
  const Reading r = read(write("mixed.obj", text));
  const CornerAttributes& c = r.attributes.corners;
  EXPECT_EQ(c.texture_components, 3);
  EXPECT_EQ(c.corner_texture, (std::vector<Index>{0, 2, 1, kNoIndex, kNoIndex, kNoIndex, kNoIndex,
                                                  kNoIndex, kNoIndex, 1, 2, 0}));
  EXPECT_EQ(c.corner_normal, (std::vector<Index>{kNoIndex, kNoIndex, kNoIndex, kNoIndex, kNoIndex,
                                                 kNoIndex, 0, 0, 0, 0, 0, 0}));
  IndexedMesh mesh;
  mesh.soup = r.soup;
  const std::string out = path("mixed_out.obj");
  write_mesh(out, mesh, &r.attributes);
  EXPECT_EQ(describe_written(out, mesh, r.attributes).left_out, std::vector<std::string>{});
  const std::vector<std::string> lines = lines_of(out);
  ASSERT_EQ(lines.size(), 13u);
  EXPECT_EQ(lines[5], "vt 0.25 0.5 0.75");
  EXPECT_EQ(lines[6], "vt 1 0 0");
  EXPECT_EQ(lines[8], "vn 0 0 -1");
  EXPECT_EQ(lines[9], "f 1/1 3/3 2/2");
  EXPECT_EQ(lines[10], "f 1 2 4");
  EXPECT_EQ(lines[11], "f 1//1 4//1 3//1");
  EXPECT_EQ(lines[12], "f 2/2/1 3/3/1 4/1/1");
  const Reading back = read(out);
  EXPECT_EQ(back.attributes.corners.corner_texture, c.corner_texture);
  EXPECT_EQ(back.attributes.corners.corner_normal, c.corner_normal);
  EXPECT_EQ(back.attributes.corners.texture_coordinates, c.texture_coordinates);
  EXPECT_EQ(back.attributes.corners.normals, c.normals);
  // Other formats hold no corner records: said, as before.
  EXPECT_EQ(describe_unwritten("x.ply", r.attributes),
            std::vector<std::string>{"3 texture coordinates (vt) and 1 normal (vn) not written: "
                                     "PLY holds none per corner (write OBJ to keep them)"});
}

TEST_F(ObjCornerAttributes, negative_indices_name_the_records_before_them) {
  const Reading r = read(write("relative.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                               "f -3/-3/-1 -2/-2/-1 -1/-1/-1\nvt 0.5 0.5\nvn 0 0 -1\n"
                               "f -3/-1/-1 -1/-4/-2 -2/4/-1\nf 1/-5 2/9 3/0\nf 1 2 3/-1\n"));
  const CornerAttributes& c = r.attributes.corners;
  EXPECT_EQ(c.corner_texture, (std::vector<Index>{0, 1, 2, 3, 0, 3, kNoIndex, kNoIndex, kNoIndex,
                                                  kNoIndex, kNoIndex, 3}));
  EXPECT_EQ(c.corner_normal, (std::vector<Index>{0, 0, 0, 1, 0, 1, kNoIndex, kNoIndex, kNoIndex,
                                                 kNoIndex, kNoIndex, kNoIndex}));
  // -5 (before the first vt), 9 (past the last) and 0 name no record: a fault, counted.
  ASSERT_EQ(r.attributes.not_kept.size(), 1u);
  EXPECT_EQ(r.attributes.not_kept[0].count, 3u);
}

TEST_F(ObjCornerAttributes, faces_hole_filling_adds_are_written_without_and_counted) {
  if (!has_hole_filling())
    GTEST_SKIP() << "built without CGAL";
  // One cube without its top: a hole of 4 sides, filled with 2 triangles.
  const std::string in = write("open_cube.obj", textured_cubes({{0, 0, 0}}, {5}));
  RepairFileOptions options;
  options.keep_meshes = true;
  options.repair.fill_holes.max_edges = kDefaultFillHolesMaxEdges;
  const std::string out = path("open_cube_out.obj");
  const RepairedFile file = repair_file(in, out, options);
  ASSERT_EQ(file.report.holes.faces_added, 2u);
  EXPECT_EQ(file.written.left_out,
            std::vector<std::string>{"2 faces added by hole filling written without texture "
                                     "coordinates (vt) and normals (vn): they have no input "
                                     "corner to take them from"});
  std::size_t plain = 0, textured = 0;
  for (const std::string& line : lines_of(out)) {
    if (line.rfind("f ", 0) != 0)
      continue;
    plain += line.find('/') == std::string::npos;
    textured += std::count(line.begin(), line.end(), '/') == 8;
  }
  EXPECT_EQ(plain, 2u);
  EXPECT_EQ(textured, 5u);
  const Reading input = read(in), output = read(out);
  EXPECT_EQ(corners_carried(input.attributes, file, output.attributes), 20u);
}

}  // namespace
}  // namespace meshbridge
