// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a file in parts on several threads gives the soup, the counts and the errors of the
// one-thread read, bit for bit (MESHBRIDGE_THREADS picks the number of threads; files are made
// large enough to be cut, and shuffled so that vertices are first met in every part).
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"

#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using namespace meshbridge;

namespace {

using test_support::ThreadsSetting;

struct Reading {
  Soup soup;
  ReadInfo info;
  MeshAttributes attributes;
  std::string error;  // the message, if the read threw
};

Reading read_with(unsigned threads, const std::string& path) {
  const ThreadsSetting setting(threads);
  Reading r;
  try {
    r.soup = read_soup(path, &r.info, &r.attributes);
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

//! `read_past`: compare what was read past too (not between formats: an ASCII STL names its
//! solid, a binary one has none).
::testing::AssertionResult same_reading(const Reading& a, const Reading& b, bool read_past = true) {
  if (a.error != b.error)
    return ::testing::AssertionFailure()
           << "errors differ: '" << a.error << "' / '" << b.error << "'";
  // Bit for bit (-0 and NaN payloads included); memcmp only on non-empty arrays (an error's
  // empty soup has no data pointer).
  if (a.soup.positions.size() != b.soup.positions.size() ||
      (!a.soup.positions.empty() && std::memcmp(a.soup.positions.data(), b.soup.positions.data(),
                                                a.soup.positions.size() * sizeof(Point)) != 0))
    return ::testing::AssertionFailure() << "positions differ";
  if (a.soup.face_begin != b.soup.face_begin)
    return ::testing::AssertionFailure() << "face offsets differ";
  if (a.soup.corner_vertices != b.soup.corner_vertices) {
    std::size_t c = 0;
    while (a.soup.corner_vertices[c] == b.soup.corner_vertices[c])
      ++c;
    return ::testing::AssertionFailure()
           << "corner " << c << " differs: " << a.soup.corner_vertices[c] << " / "
           << b.soup.corner_vertices[c];
  }
  const ReadInfo &x = a.info, &y = b.info;
  if (x.declared_vertices != y.declared_vertices || x.declared_faces != y.declared_faces ||
      x.faces_kept != y.faces_kept || x.faces_split != y.faces_split ||
      x.faces_set_aside != y.faces_set_aside ||
      x.faces_without_corners != y.faces_without_corners || x.dangling_edges != y.dangling_edges ||
      x.lone_points != y.lone_points || x.unknown_records != y.unknown_records ||
      x.color_map_indices != y.color_map_indices || x.empty_records != y.empty_records ||
      x.trailing_bytes != y.trailing_bytes)
    return ::testing::AssertionFailure() << "counts differ";
  const MeshAttributes &s = a.attributes, &t = b.attributes;
  if (!(s.vertex_colors == t.vertex_colors) || !(s.face_colors == t.face_colors) ||
      s.vertex_color_missing != t.vertex_color_missing ||
      s.face_color_missing != t.face_color_missing ||
      s.vertex_color_channels != t.vertex_color_channels ||
      s.face_color_channels != t.face_color_channels || s.double_precision != t.double_precision)
    return ::testing::AssertionFailure() << "colours differ";
  if (s.material_libraries != t.material_libraries ||
      s.texture_coordinates != t.texture_coordinates || s.normals != t.normals)
    return ::testing::AssertionFailure() << "mtllib, vt or vn counts differ";
  if (read_past && s.not_kept.size() != t.not_kept.size())
    return ::testing::AssertionFailure() << "read-past lists differ";
  for (std::size_t k = 0; read_past && k < s.not_kept.size(); ++k) {
    if (s.not_kept[k].what != t.not_kept[k].what || s.not_kept[k].count != t.not_kept[k].count)
      return ::testing::AssertionFailure() << "read past: '" << s.not_kept[k].what << "' differs";
  }
  const CornerAttributes &u = s.corners, &w = t.corners;
  if (u.texture_coordinates != w.texture_coordinates || u.normals != w.normals ||
      u.texture_components != w.texture_components)
    return ::testing::AssertionFailure() << "vt or vn records differ";
  if (u.corner_texture != w.corner_texture || u.corner_normal != w.corner_normal)
    return ::testing::AssertionFailure() << "vt or vn of the corners differ";
  if (a.attributes.face_groups.size() != b.attributes.face_groups.size())
    return ::testing::AssertionFailure() << "groups differ";
  for (std::size_t g = 0; g < a.attributes.face_groups.size(); ++g) {
    if (a.attributes.face_groups[g].name != b.attributes.face_groups[g].name ||
        a.attributes.face_groups[g].first_face != b.attributes.face_groups[g].first_face)
      return ::testing::AssertionFailure() << "group " << g << " differs";
  }
  return ::testing::AssertionSuccess();
}

class ParallelReading : public test_support::ScratchFolderTest {
 protected:
  ParallelReading() : ScratchFolderTest("parallel") {}
  // 20 x 20 x 20 checkerboard cubes (48,000 triangles, singular edges everywhere), faces
  // shuffled, one corner at -0 and a facet with one point three times.
  static IndexedMesh test_mesh() {
    Soup soup = test_support::shuffled(models::checkerboard_cubes(20), 7);
    soup.positions[soup.corner_vertices[5]][0] = -0.0;
    const Index v = soup.corner_vertices[3 * 30000];
    soup.add_polygon({v, v, v});
    IndexedMesh mesh;
    mesh.soup = std::move(soup);
    return mesh;
  }
  // Every thread count gives the one-thread reading.
  void expect_same_for_every_thread_count(const std::string& file) {
    const Reading one = read_with(1, file);
    for (unsigned threads : {2u, 3u, 4u, 7u})
      EXPECT_TRUE(same_reading(one, read_with(threads, file))) << file << ", " << threads;
  }
};

TEST_F(ParallelReading, binary_and_ascii_stl_weld_the_same_in_parts) {
  const IndexedMesh mesh = test_mesh();
  const std::string binary = path("board.stl"), ascii = path("board_ascii.stl");
  write_mesh(binary, mesh);
  WriteOptions text;
  text.binary = false;
  write_mesh(ascii, mesh, nullptr, text);
  const Reading one = read_with(1, binary);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(one.info.faces_set_aside, 1u);
  EXPECT_LT(one.soup.num_vertices(), mesh.soup.num_vertices() + 1);
  expect_same_for_every_thread_count(binary);
  expect_same_for_every_thread_count(ascii);
  EXPECT_TRUE(same_reading(one, read_with(2, ascii), false));
}

// Parts whose tables differ in size: the first half of the file is a soup of distinct corners
// (its table grows), the second half reuses them with a new point now and then. Every part after
// the first must find its positions in the earlier parts' tables however large each grew.
TEST_F(ParallelReading, binary_stl_parts_of_unlike_vertex_counts_weld_the_same) {
  Soup soup;
  constexpr Index kSoup = 30000;  // triangles of distinct corners
  for (Index t = 0; t < kSoup; ++t) {
    for (int k = 0; k < 3; ++k)
      soup.add_vertex(Point(t, k, 0.5 * t + k));
    soup.add_polygon({3 * t, 3 * t + 1, 3 * t + 2});
  }
  std::size_t fresh = 0;
  for (Index t = 0; t < kSoup; ++t) {
    Index third = (7 * t + 2) % (3 * kSoup);
    if (t % 100 == 0) {
      third = soup.add_vertex(Point(-1.0 - t, 0, 0));
      ++fresh;
    }
    soup.add_polygon({(7 * t) % (3 * kSoup), (7 * t + 1) % (3 * kSoup), third});
  }
  IndexedMesh mesh;
  mesh.soup = std::move(soup);
  const std::string file = path("unlike.stl");
  write_mesh(file, mesh);
  const Reading one = read_with(1, file);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(one.soup.num_vertices(), 3 * kSoup + fresh);
  EXPECT_EQ(one.soup.num_faces(), 2u * kSoup);
  expect_same_for_every_thread_count(file);
}

TEST_F(ParallelReading, binary_stl_names_the_first_non_finite_corner_in_file_order) {
  const IndexedMesh mesh = test_mesh();
  const std::string file = path("nan.stl");
  write_mesh(file, mesh);
  std::fstream bytes(file, std::ios::in | std::ios::out | std::ios::binary);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // Triangle 40000 (last part), then triangle 20000 (a middle part), corner 1, y (0-based;
  // messages count from 1).
  for (const auto& [triangle, value] : {std::pair<long, float>{40000, inf}, {20000, nan}}) {
    bytes.seekp(84 + 50 * triangle + 12 + 12 + 4);
    bytes.write(reinterpret_cast<const char*>(&value), 4);
  }
  bytes.close();
  const Reading one = read_with(1, file);
  EXPECT_NE(one.error.find("facet 20001, corner 2 has a non-finite"), std::string::npos)
      << one.error;
  expect_same_for_every_thread_count(file);
}

// A binary little-endian PLY of `soup` as `list uchar int vertex_indices` faces, with float
// vertices that carry one extra property (so their records are not just x, y, z).
void write_plain_ply(const std::string& file, const Soup& soup) {
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << soup.num_vertices()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar flags\n"
      << "element face " << soup.num_faces() << "\nproperty list uchar int vertex_indices\n"
      << "end_header\n";
  for (const Point& p : soup.positions) {
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    out.write(reinterpret_cast<const char*>(xyz), 12);
    out.put(7);
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    out.put(static_cast<char>(soup.arity(f)));
    for (Index v : soup.polygon(f)) {
      const std::int32_t i = static_cast<std::int32_t>(v);
      out.write(reinterpret_cast<const char*>(&i), 4);
    }
  }
}

TEST_F(ParallelReading, binary_ply_vertices_and_faces_read_the_same_in_parts) {
  const Soup board = test_support::shuffled(models::checkerboard_cubes(20), 3);
  const std::string plain = path("board.ply"), written = path("board_written.ply");
  write_plain_ply(plain, board);
  IndexedMesh mesh;
  mesh.soup = board;
  write_mesh(written, mesh);
  const Reading one = read_with(1, plain);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(one.soup.corner_vertices, board.corner_vertices);
  expect_same_for_every_thread_count(plain);
  expect_same_for_every_thread_count(written);
}

TEST_F(ParallelReading, binary_ply_faces_that_are_not_all_alike_read_the_same_in_parts) {
  const Soup board = models::checkerboard_cubes(20);
  // A quad in a late part: the records after it are 4 bytes later than a triangle's would be.
  Soup quad = board;
  quad.corner_vertices.insert(quad.corner_vertices.begin() + 3 * 40000 + 3, 0);
  for (std::size_t f = 40000 + 1; f < quad.face_begin.size(); ++f)
    ++quad.face_begin[f];
  // A negative index and an index beyond the vertices, in two different parts.
  Soup bad = board;
  bad.corner_vertices[3 * 20000 + 1] = static_cast<Index>(-5);
  bad.corner_vertices[3 * 40000 + 2] = static_cast<Index>(bad.num_vertices() + 3);
  Soup beyond = board;
  beyond.corner_vertices[3 * 40000 + 2] = static_cast<Index>(beyond.num_vertices() + 3);
  const std::string quad_file = path("quad.ply"), bad_file = path("bad.ply");
  const std::string beyond_file = path("beyond.ply");
  write_plain_ply(quad_file, quad);
  write_plain_ply(bad_file, bad);
  write_plain_ply(beyond_file, beyond);
  EXPECT_EQ(read_with(1, quad_file).soup.arity(40000), 4u);
  // The negative index comes first in the file and is named as written.
  EXPECT_NE(read_with(1, bad_file).error.find("face 20001 refers to vertex index -5"),
            std::string::npos)
      << read_with(1, bad_file).error;
  EXPECT_NE(read_with(1, beyond_file).error.find("face 40001, corner 3"), std::string::npos)
      << read_with(1, beyond_file).error;
  expect_same_for_every_thread_count(quad_file);
  expect_same_for_every_thread_count(bad_file);
  expect_same_for_every_thread_count(beyond_file);
}

// An OBJ of `soup` with everything a part boundary could cut: vertices written just before the
// first face that needs them, every third face with negative (relative) indices that reach back
// across parts, colours on some vertices of the second half only, groups, l and p records,
// comments, line continuations and CRLF line ends here and there.
void write_busy_obj(const std::string& file, const Soup& soup) {
  std::ofstream out(file, std::ios::binary);
  std::size_t written = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    for (Index v : soup.polygon(f)) {
      for (; written <= v; ++written) {
        const Point& p = soup.positions[written];
        out << "v " << p[0] << ' ' << p[1] << ' ' << p[2];
        if (written > soup.num_vertices() / 2 && written % 100 < 5)
          out << " 0.25 0.5 1" << (written % 100 == 3 ? " 0.5" : "");
        out << (written % 31 == 0 ? "\r\n" : "\n");
      }
    }
    if (f % 5000 == 0) {
      out << (f % 10000 == 0 ? "g part" : "usemtl m") << f << "\n# a comment \\\ns 1\n";
      out << "mtllib lib" << f << ".mtl\nvt 0.5 0.5\nvn 0 0 1\nvn 1 0 0\n";
    }
    if (f % 4001 == 0)
      out << "l 1 2 -1\np -2\n";
    out << "f";
    int i = 0;
    for (Index v : soup.polygon(f)) {
      if (f % 3 == 0)
        out << " -" << written - v << (f % 6 == 0 ? "/-1/-2" : "");
      else
        out << ' ' << v + 1 << (f % 3 == 1 ? "//1" : "");
      if (f % 97 == 0 && i++ == 1)
        out << " \\\n";
    }
    out << "\n";
  }
}

TEST_F(ParallelReading, obj_with_relative_indices_groups_and_colors_reads_the_same_in_parts) {
  const Soup board = test_support::shuffled(models::checkerboard_cubes(30), 5);
  const std::string file = path("busy.obj");
  write_busy_obj(file, board);
  const Reading one = read_with(1, file);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(one.soup.num_faces(), board.num_faces());
  EXPECT_GT(one.info.dangling_edges, 0u);
  EXPECT_EQ(one.attributes.vertex_colors.size(), one.soup.num_vertices());
  ASSERT_EQ(one.attributes.vertex_color_missing.size(), one.soup.num_vertices());
  std::size_t colored = 0;
  for (std::size_t v = 0; v < one.soup.num_vertices(); ++v) {
    const bool has = v > one.soup.num_vertices() / 2 && v % 100 < 5;
    colored += has;
    EXPECT_EQ(one.attributes.vertex_color_missing[v], !has) << v;
  }
  EXPECT_GT(colored, 0u);
  EXPECT_EQ(one.attributes.vertex_color_channels, kRgbaChannels);  // some 'v' has r g b a
  const std::size_t group_lines = (board.num_faces() + 4999) / 5000;
  EXPECT_EQ(one.attributes.material_libraries.size(), group_lines);
  EXPECT_EQ(one.attributes.material_libraries.front(), "mtllib lib0.mtl");
  EXPECT_EQ(one.attributes.texture_coordinates, group_lines);
  EXPECT_EQ(one.attributes.normals, 2 * group_lines);
  // Every sixth face names the last vt and the last vn but one by relative indices; every
  // third but those, the first vn.
  const CornerAttributes& kept = one.attributes.corners;
  ASSERT_EQ(kept.corner_texture.size(), one.soup.num_corners());
  ASSERT_EQ(kept.corner_normal.size(), one.soup.num_corners());
  std::size_t textured = 0, normal_first = 0;
  for (std::size_t f = 0; f < one.soup.num_faces(); ++f) {
    const Index c = one.soup.face_begin[f];
    const Index group = static_cast<Index>(f / 5000);
    if (f % 6 == 0) {
      textured += kept.corner_texture[c] == group && kept.corner_normal[c] == 2 * group;
    } else if (f % 3 == 1) {
      normal_first += kept.corner_texture[c] == kNoIndex && kept.corner_normal[c] == 0;
    }
  }
  EXPECT_EQ(textured, (one.soup.num_faces() + 5) / 6);
  EXPECT_EQ(normal_first, (one.soup.num_faces() + 1) / 3);
  EXPECT_FALSE(one.attributes.face_groups.empty());
  expect_same_for_every_thread_count(file);
}

TEST_F(ParallelReading, obj_vt_and_vn_indices_without_a_record_are_counted_in_parts) {
  const Soup board = test_support::shuffled(models::checkerboard_cubes(30), 5);
  const std::string clean = path("clean.obj"), broken = path("broken.obj");
  write_busy_obj(clean, board);
  const auto no_record = [](const Reading& r) {
    for (const NotKept& n : r.attributes.not_kept) {
      if (n.what.find("has no record for") != std::string::npos)
        return n.count;
    }
    return std::size_t(0);
  };
  EXPECT_EQ(no_record(read_with(1, clean)), 0u);
  {
    std::ofstream out(broken, std::ios::binary);
    out << std::ifstream(clean, std::ios::binary).rdbuf();
    // Relative vt -2 and vn -3 reach back to records of earlier parts: fine. Then a vt past the
    // last, a vn before the first, an index 0 (one corner with two faults counts once); an
    // index 0 alone in the last part.
    out << "f 1/-2/-3 2/1 3//2\nf 1/999999 2/1/999999 3/0/-999999\nf 4/1 5//-99999999 6\n"
        << "f 7/1/0 8/1/1 9/1/1\n";
  }
  const Reading one = read_with(1, broken);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(no_record(one), 5u);
  expect_same_for_every_thread_count(broken);
  // The only fault an index 0 in the last part: found by every thread count.
  const std::string zero = path("zero.obj");
  {
    std::ofstream out(zero, std::ios::binary);
    out << std::ifstream(clean, std::ios::binary).rdbuf() << "f 1/1 2/0 3/1\n";
  }
  for (unsigned threads : {1u, 2u, 4u})
    EXPECT_EQ(no_record(read_with(threads, zero)), 1u) << threads;
  // An l or p corner past the last vertex, in the last part: the same error for every count.
  const std::string past = path("past.obj");
  {
    std::ofstream out(past, std::ios::binary);
    out << std::ifstream(clean, std::ios::binary).rdbuf() << "p 99999999\n";
  }
  const Reading point = read_with(1, past);
  EXPECT_NE(point.error.find("point corner '99999999' refers to vertex 99999999"),
            std::string::npos)
      << point.error;
  expect_same_for_every_thread_count(past);
}

TEST_F(ParallelReading, obj_whose_faces_the_size_estimate_misses_reads_every_record) {
  // Over 8 MiB, so the reader estimates its records from 32 stretches of 64 KiB, one at the
  // start of each 32nd of the file. Every face here lies between two stretches: the estimate
  // counts none, and the arrays must grow as the faces come.
  constexpr std::size_t kStratum = 300 * 1024, kSize = 32 * kStratum;
  std::string text;
  std::size_t vertices = 0, faces = 0;
  while (text.size() < kSize) {
    const std::size_t at = text.size() % kStratum;
    if (text.size() / kStratum == 5 && at > 100 * 1024 && at < 290 * 1024) {
      text += "f 1 2 " + std::to_string(vertices) + "\n";
      ++faces;
    } else {
      text += "v " + std::to_string(vertices) + " 0.5 0.25\n";
      ++vertices;
    }
  }
  const std::string file = path("faces_between_samples.obj");
  std::ofstream(file, std::ios::binary) << text;
  const Reading one = read_with(1, file);
  ASSERT_EQ(one.error, "");
  EXPECT_EQ(one.soup.num_vertices(), vertices);
  EXPECT_EQ(one.soup.num_faces(), faces);
  EXPECT_GT(faces, 5000u);
  EXPECT_EQ(one.info.faces_kept, faces);
  EXPECT_EQ(one.soup.polygon(faces - 1)[0], 0u);
  EXPECT_EQ(one.soup.polygon(faces - 1)[2], one.soup.polygon(0)[2]);  // the last vertex before
  expect_same_for_every_thread_count(file);
}

TEST_F(ParallelReading, obj_errors_in_later_parts_are_named_as_by_one_thread) {
  const Soup board = models::checkerboard_cubes(30);
  const std::string clean = path("clean.obj");
  write_busy_obj(clean, board);
  std::ifstream in(clean, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // A relative index before the first vertex near the end, then a bad number later still; and
  // the other way round.
  const std::size_t late = text.find("\nf ", text.size() * 3 / 4);
  const std::size_t later = text.find("\nv ", text.size() * 7 / 8);
  const std::string before_first = path("before_first.obj"), bad_number = path("bad_number.obj");
  std::ofstream(before_first, std::ios::binary)
      << text.substr(0, late) << "\nf 1 2 -99999999" << text.substr(late, later - late)
      << "\nv 1 2 x" << text.substr(later);
  std::ofstream(bad_number, std::ios::binary)
      << text.substr(0, late) << "\nv 1 2 x" << text.substr(late, later - late)
      << "\nf 1 2 -99999999" << text.substr(later);
  const Reading one = read_with(1, before_first);
  EXPECT_NE(one.error.find("before the first vertex"), std::string::npos) << one.error;
  EXPECT_NE(read_with(1, bad_number).error.find("is not a number"), std::string::npos);
  expect_same_for_every_thread_count(before_first);
  expect_same_for_every_thread_count(bad_number);
}

TEST_F(ParallelReading, obj_color_scale_is_one_per_file_across_parts) {
  // 0s and 1s in the first part, one 0..255 colour in the last: every part reads "1 1 1" as
  // near black, as one thread does.
  const std::string file = path("scale.obj");
  {
    std::ofstream out(file, std::ios::binary);
    out << "v 0 0 0 1 1 1\n";
    for (int i = 0; i < 100000; ++i)
      out << "v " << i << " 0.123456789 0.987654321 0.5 0.5 0.5\n";
    out << "v 0 0 1 1 1 1\nv 0 1 0 255 128 0\nf 1 2 3\nf 100001 100002 100003\n";
  }
  const Reading one = read_with(1, file);
  ASSERT_TRUE(one.error.empty()) << one.error;
  const auto& c = one.attributes.vertex_colors;
  ASSERT_EQ(c.size(), 100003u);
  EXPECT_EQ(c[0], (Rgba{1, 1, 1, 255}));
  EXPECT_EQ(c[1], (Rgba{128, 128, 128, 255}));  // a fraction: 0..1 in any file
  EXPECT_EQ(c[100001], (Rgba{1, 1, 1, 255}));
  EXPECT_EQ(c[100002], (Rgba{255, 128, 0, 255}));
  expect_same_for_every_thread_count(file);
}

}  // namespace
