// SPDX-License-Identifier: GPL-3.0-or-later
// MeshBridge's PLY and STL readers and writers: cross-checked against OpenMesh's readers on the
// real-world corpus and the canonical models, round trips that change nothing, and the cases
// OpenMesh's readers lose (triangle strips, edge elements, facets with a repeated point) with
// exact counts.
//
// Expected differences from OpenMesh's readers (everything else must be equal):
//  - STL facets whose corners weld to fewer than 3 vertices: OpenMesh drops them, MeshBridge
//    keeps them in the soup and counts them in faces_set_aside;
//  - PLY `tristrips`: OpenMesh reads none ("no polygons"); PLY `edge`: OpenMesh ignores them;
//  - PLY `double` positions: OpenMesh rounds them to float, MeshBridge keeps the doubles.
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include "openmesh_reference_reader.h"
#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <dirent.h>
#include <unistd.h>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#ifndef MESHBRIDGE_REALWORLD_DIR
#error "define MESHBRIDGE_REALWORLD_DIR as the path of tests/data/realworld"
#endif

using namespace meshbridge;
using meshbridge::test_support::read_with_openmesh;

namespace {

class PlyStlIo : public meshbridge::test_support::ScratchFolderTest {
 protected:
  PlyStlIo() : ScratchFolderTest("plystl") {}
};

template <class T>
void put(std::string& out, T value, bool big_endian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
      std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  }
  out.append(bytes, sizeof(T));
}

//! Soups equal in every position (exactly) and every polygon.
::testing::AssertionResult same_soup(const Soup& a, const Soup& b) {
  if (a.positions.size() != b.positions.size())
    return ::testing::AssertionFailure()
           << a.num_vertices() << " vs " << b.num_vertices() << " vertices";
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    if (!(a.positions[v] == b.positions[v]))
      return ::testing::AssertionFailure() << "vertex " << v << " differs";
  }
  if (a.face_begin != b.face_begin)
    return ::testing::AssertionFailure()
           << a.num_faces() << " vs " << b.num_faces() << " faces (or their arities differ)";
  if (a.corner_vertices != b.corner_vertices)
    return ::testing::AssertionFailure() << "corner vertices differ";
  return ::testing::AssertionSuccess();
}

IndexedMesh as_mesh(const Soup& soup) {
  IndexedMesh mesh;
  mesh.soup = soup;
  return mesh;
}

//! The soup with every coordinate rounded to float (what a float format keeps).
//! (Through a volatile: GCC 12.2 at -O2 drops `p[i] = static_cast<float>(p[i])` for two of the
//! three coordinates of such a loop, a miscompilation seen while writing this test.)
Soup rounded_to_float(Soup soup) {
  for (Point& p : soup.positions) {
    for (int i = 0; i < 3; ++i) {
      volatile float rounded = static_cast<float>(p[i]);
      p[i] = rounded;
    }
  }
  return soup;
}

std::vector<std::string> realworld_files(const std::string& ext_lower) {
  std::vector<std::string> files;
  const std::string dir = MESHBRIDGE_REALWORLD_DIR;
  DIR* d = opendir(dir.c_str());
  while (dirent* e = d != nullptr ? readdir(d) : nullptr) {
    std::string name = e->d_name;
    std::string lower = name;
    for (char& c : lower)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, "." + ext_lower) == 0)
      files.push_back(dir + "/" + name);
  }
  if (d != nullptr)
    closedir(d);
  return files;
}

const std::vector<std::pair<const char*, Soup (*)()>> kModels = {
    {"twocubes", models::two_cubes_sharing_edge},
    {"hourglass", models::hourglass},
    {"bowtie", models::bowtie},
    {"book_of_three", models::book_of_three},
};

}  // namespace

// --- differential: OpenMesh's readers as the cross-check -------------------------------------

TEST_F(PlyStlIo, realworld_ply_reads_as_openmesh_reads_it_colors_included) {
  const auto files = realworld_files("ply");
  ASSERT_EQ(files.size(), 2u);
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    MeshAttributes attributes;
    ReadInfo info;
    const Soup ours = read_soup(file, &info, &attributes);
    const auto theirs = read_with_openmesh(file, true);
    ASSERT_TRUE(theirs.ok);
    EXPECT_TRUE(same_soup(ours, theirs.soup));
    EXPECT_EQ(info.declared_faces, ours.num_faces());
    EXPECT_EQ(info.faces_kept + info.faces_split + info.faces_set_aside, info.declared_faces);
    ASSERT_EQ(attributes.vertex_colors.size(), theirs.vertex_colors.size());
    for (std::size_t v = 0; v < theirs.vertex_colors.size(); ++v) {
      const Rgba c = attributes.vertex_colors[v];
      ASSERT_EQ(OpenMesh::Vec4uc(c.r, c.g, c.b, c.a), theirs.vertex_colors[v]) << "vertex " << v;
    }
    ASSERT_EQ(attributes.face_colors.size(), theirs.face_colors.size());
    for (std::size_t f = 0; f < theirs.face_colors.size(); ++f) {
      const Rgba c = attributes.face_colors[f];
      ASSERT_EQ(OpenMesh::Vec4uc(c.r, c.g, c.b, c.a), theirs.face_colors[f]) << "face " << f;
    }
  }
  // trimesh_cycloidal.ply carries RGBA per vertex and per face.
  MeshAttributes attributes;
  const Soup cycloidal = read_soup(std::string(MESHBRIDGE_REALWORLD_DIR) + "/trimesh_cycloidal.ply",
                                   nullptr, &attributes);
  EXPECT_EQ(attributes.vertex_colors.size(), 21384u);
  EXPECT_EQ(attributes.face_colors.size(), 43368u);
}

TEST_F(PlyStlIo, realworld_stl_reads_as_openmesh_reads_it) {
  const auto files = realworld_files("stl");
  ASSERT_EQ(files.size(), 4u);
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    ReadInfo info;
    const Soup ours = read_soup(file, &info);
    const auto theirs = read_with_openmesh(file);
    ASSERT_TRUE(theirs.ok);
    // OpenMesh parses ascii STL numbers as float, MeshBridge as double: compare as floats.
    EXPECT_TRUE(same_soup(rounded_to_float(ours), theirs.soup));
    EXPECT_EQ(info.declared_faces, ours.num_faces());
    EXPECT_EQ(info.faces_kept, ours.num_faces());
  }
}

TEST_F(PlyStlIo, openmesh_written_ply_and_stl_of_every_encoding_read_the_same) {
  // A clean model that OpenMesh can hold, written by OpenMesh's writers in every encoding.
  const Soup torus = models::torus_grid(12, 7);
  OpenMesh::PolyMesh_ArrayKernelT<> mesh;
  for (const Point& p : torus.positions)
    mesh.add_vertex(OpenMesh::Vec3f(p));
  for (std::size_t f = 0; f < torus.num_faces(); ++f) {
    std::vector<OpenMesh::VertexHandle> vs;
    for (Index v : torus.polygon(f))
      vs.emplace_back(static_cast<int>(v));
    ASSERT_TRUE(mesh.add_face(vs).is_valid());
  }
  using O = OpenMesh::IO::Options;
  const std::vector<std::pair<std::string, O>> encodings = {{"ascii.ply", O()},
                                                            {"le.ply", O(O::Binary | O::LSB)},
                                                            {"be.ply", O(O::Binary | O::MSB)},
                                                            {"ascii.stl", O()},
                                                            {"binary.stl", O(O::Binary)}};
  for (const auto& [name, options] : encodings) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(OpenMesh::IO::write_mesh(mesh, path(name), options, 17));
    const Soup ours = read_soup(path(name));
    const auto theirs = read_with_openmesh(path(name));
    ASSERT_TRUE(theirs.ok);
    EXPECT_TRUE(same_soup(rounded_to_float(ours), theirs.soup));
    EXPECT_EQ(ours.num_faces(), torus.num_faces());
  }
}

// --- round trips ---------------------------------------------------------------------------

TEST_F(PlyStlIo, ply_round_trips_are_identical_in_both_encodings) {
  for (const auto& [name, make] : kModels) {
    SCOPED_TRACE(name);
    const Soup soup = make();
    for (bool binary : {true, false}) {
      WriteOptions options;
      options.binary = binary;
      const std::string file = path(std::string(name) + (binary ? "_bin.ply" : "_ascii.ply"));
      write_mesh(file, as_mesh(soup), nullptr, options);
      EXPECT_TRUE(same_soup(read_soup(file), soup));
      // And OpenMesh reads our file the same, but rounds our doubles to floats.
      const auto theirs = read_with_openmesh(file);
      ASSERT_TRUE(theirs.ok);
      EXPECT_TRUE(same_soup(theirs.soup, rounded_to_float(soup)));
    }
  }
  // Colours and doubles survive: the real-world file with RGBA, and a position only a double holds.
  MeshAttributes attributes;
  const std::string cycloidal = std::string(MESHBRIDGE_REALWORLD_DIR) + "/trimesh_cycloidal.ply";
  const Soup colored = read_soup(cycloidal, nullptr, &attributes);
  write_mesh(path("colors.ply"), as_mesh(colored), &attributes);
  MeshAttributes again;
  EXPECT_TRUE(same_soup(read_soup(path("colors.ply"), nullptr, &again), colored));
  EXPECT_EQ(again.vertex_colors, attributes.vertex_colors);
  EXPECT_EQ(again.face_colors, attributes.face_colors);
  EXPECT_FALSE(again.double_precision);

  Soup precise = models::bowtie();
  precise.positions[0] = Point(0.1, 1.0 / 3.0, -2e-300);
  write_mesh(path("precise.ply"), as_mesh(precise));
  MeshAttributes precise_attributes;
  EXPECT_TRUE(same_soup(read_soup(path("precise.ply"), nullptr, &precise_attributes), precise));
  EXPECT_TRUE(precise_attributes.double_precision);
}

TEST_F(PlyStlIo, stl_round_trips_are_identical_for_float_positions) {
  for (const auto& [name, make] : kModels) {
    SCOPED_TRACE(name);
    // STL keeps floats and welds by position: a float soup without coincident vertices returns
    // with the same vertices in order of first appearance, which these models have.
    const Soup soup = rounded_to_float(make());
    for (bool binary : {true, false}) {
      WriteOptions options;
      options.binary = binary;
      const std::string file = path(std::string(name) + (binary ? "_bin.stl" : "_ascii.stl"));
      write_mesh(file, as_mesh(soup), nullptr, options);
      const Soup back = read_soup(file);
      const auto theirs = read_with_openmesh(file);
      ASSERT_TRUE(theirs.ok);
      EXPECT_TRUE(same_soup(rounded_to_float(back), theirs.soup));
      // Written again, the file is byte for byte the same.
      write_mesh(path("again.stl"), as_mesh(back), nullptr, options);
      std::ifstream a(file, std::ios::binary), b(path("again.stl"), std::ios::binary);
      const std::string first((std::istreambuf_iterator<char>(a)), {});
      const std::string second((std::istreambuf_iterator<char>(b)), {});
      EXPECT_EQ(first, second);
      EXPECT_EQ(back.num_faces(), soup.num_faces());
    }
  }
}

TEST_F(PlyStlIo, a_binary_stl_of_double_positions_reads_and_writes_back_to_the_same_bytes) {
  // Normals are those of the corners as stored (floats), not of the doubles they came from, so
  // repairing a repaired STL again changes no byte.
  const auto bytes = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  for (const auto& [name, make] : kModels) {
    SCOPED_TRACE(name);
    Soup soup = make();
    for (Point& p : soup.positions)  // no coordinate a float
      p = p * (1.0 + 1e-12) + Point(1e-9, -1e-9, 1e-9);
    const std::string file = path(std::string(name) + "_double.stl");
    write_mesh(file, as_mesh(soup));
    write_mesh(path("again.stl"), as_mesh(read_soup(file)));
    EXPECT_EQ(bytes(file), bytes(path("again.stl")));
  }
}

TEST_F(PlyStlIo, stl_keeps_negative_zeros_so_a_round_trip_keeps_every_byte) {
  const auto bytes = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
  };
  // Two cubes with a corner at the origin, every 0 written as -0 (as mirrored CAD parts are).
  Soup cube = models::two_cubes_sharing_edge();
  std::size_t negative = 0;
  for (Point& p : cube.positions) {
    for (int k = 0; k < 3; ++k) {
      if (p[k] == 0) {
        p[k] = -0.0;
        ++negative;
      }
    }
  }
  ASSERT_GT(negative, 0u);
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    WriteOptions options;
    options.binary = binary;
    const std::string file = path(binary ? "minus_zero_bin.stl" : "minus_zero_ascii.stl");
    write_mesh(file, as_mesh(cube), nullptr, options);
    const Soup back = read_soup(file);
    std::size_t back_negative = 0;
    for (const Point& p : back.positions)
      for (int k = 0; k < 3; ++k)
        back_negative += p[k] == 0 && std::signbit(p[k]);
    EXPECT_EQ(back_negative, negative);
    write_mesh(path("again.stl"), as_mesh(back), nullptr, options);
    EXPECT_EQ(bytes(file), bytes(path("again.stl")));
  }
  // -0 and +0 are one position: welded, the vertex keeps the sign its first corner had.
  Soup mixed;
  for (const Point& p :
       {Point(-0.0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0.0, 0, 0), Point(0, 0, 1)})
    mixed.add_vertex(p);
  mixed.add_polygon({0, 1, 2});
  mixed.add_polygon({3, 2, 4});
  write_mesh(path("mixed.stl"), as_mesh(mixed));
  const Soup welded = read_soup(path("mixed.stl"));
  ASSERT_EQ(welded.num_vertices(), 4u);
  EXPECT_TRUE(std::signbit(welded.positions[0][0]));
  EXPECT_EQ(welded.corner_vertices[3], 0u);
}

TEST_F(PlyStlIo, coordinates_beyond_32_bit_floats_are_refused_by_stl_and_3mf_not_written_inf) {
  Soup soup;
  soup.positions = {Point(0, 0, 0), Point(1e300, 0, 0), Point(0, 1, 0)};
  soup.add_polygon({0, 1, 2});
  for (const char* name : {"huge.stl", "huge_ascii.stl", "huge.3mf"}) {
    SCOPED_TRACE(name);
    WriteOptions options;
    options.binary = std::string(name) != "huge_ascii.stl";
    const std::string file = path(name);
    try {
      write_mesh(file, as_mesh(soup), nullptr, options);
      ADD_FAILURE() << "written";
    } catch (const WriteError& e) {
      EXPECT_NE(std::string(e.what()).find(file + ": vertex 1 has coordinate 1e+300, beyond what "
                                                  "the 32-bit floats of"),
                std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(std::ifstream(file).good());  // nothing left behind
  }
  // Formats that hold doubles keep it; 3.4e38 itself still fits a float.
  write_mesh(path("huge.ply"), as_mesh(soup));
  EXPECT_EQ(read_soup(path("huge.ply")).positions[1][0], 1e300);
  soup.positions[1][0] = 3.4e38;
  write_mesh(path("big.stl"), as_mesh(soup));
  EXPECT_EQ(read_soup(path("big.stl")).positions[1][0], double(3.4e38f));
}

TEST_F(PlyStlIo, non_convex_polygons_are_cut_into_triangles_inside_them_for_stl) {
  // An L (area 3), a comb of 4 teeth (area 11) in a tilted plane, and a pinched polygon (no ear
  // test can hold: fanned as before, still n - 2 triangles).
  const auto tilt = [](double x, double y) { return Point(x, 0.6 * y, 0.8 * y); };
  Soup soup;
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}, {1, 1}})
    soup.add_vertex(Point(x, y, 0));
  soup.add_polygon({0, 1, 2, 3, 4, 5});
  const std::vector<std::pair<double, double>> teeth = {
      {0, 0}, {7, 0}, {7, 2}, {6, 2}, {6, 1}, {5, 1}, {5, 2}, {4, 2},
      {4, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<Index> ring;
  for (const auto& [x, y] : teeth) {
    ring.push_back(static_cast<Index>(soup.num_vertices()));
    soup.add_vertex(tilt(x, y));
  }
  soup.add_polygon(ring);
  const std::string file = path("polygons.stl");
  write_mesh(file, as_mesh(soup));
  const Soup back = read_soup(file);
  ASSERT_EQ(back.num_faces(), 4u + (teeth.size() - 2));
  // Every triangle runs the polygon's way round (a fan of a non-convex polygon has triangles
  // that run the other way, reaching outside it), and their areas add up to the polygon's.
  const auto area = [&](std::size_t f, const Point& normal) {
    const PolygonView t = back.polygon(f);
    const Point& a = back.positions[t[0]];
    return 0.5 * (((back.positions[t[1]] - a) % (back.positions[t[2]] - a)) | normal);
  };
  double l_area = 0, comb_area = 0;
  const Point up(0, 0, 1), tilted(0, -0.8, 0.6);
  for (std::size_t f = 0; f < 4; ++f) {
    EXPECT_GT(area(f, up), 0) << f;
    l_area += area(f, up);
  }
  for (std::size_t f = 4; f < back.num_faces(); ++f) {
    EXPECT_GT(area(f, tilted), 1e-9) << f;
    comb_area += area(f, tilted);
  }
  EXPECT_NEAR(l_area, 3.0, 1e-6);
  EXPECT_NEAR(comb_area, 11.0, 1e-5);
  // A pinched polygon (a vertex twice) is split as repair splits it: two triangles, not a fan of
  // four with two degenerate ones (a write of an unrepaired soup, as Python's write does).
  Soup pinched;
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {1, 1}, {-1, 0}, {-1, -1}})
    pinched.add_vertex(Point(x, y, 0));
  pinched.add_polygon({0, 1, 2, 0, 3, 4});
  pinched.add_polygon({1, 2, 2, 3});  // a consecutive repeat: one triangle
  const RepairResult split = repair(pinched);
  for (bool binary : {true, false}) {
    WriteOptions options;
    options.binary = binary;
    write_mesh(path("pinched.stl"), as_mesh(pinched), nullptr, options);
    ReadInfo info;
    const Soup back = read_soup(path("pinched.stl"), &info);
    EXPECT_EQ(back.num_faces(), 3u);
    EXPECT_EQ(info.declared_faces, 3u);
    EXPECT_EQ(info.faces_set_aside, 0u);
    EXPECT_EQ(back.num_faces(), split.mesh.soup.num_faces());
  }
  EXPECT_EQ(describe_written(path("pinched.stl"), pinched, MeshAttributes()).triangles, 3u);
  write_mesh(path("pinched.3mf"), as_mesh(pinched));  // (lib3mf refuses degenerate triangles)
  EXPECT_EQ(read_soup(path("pinched.3mf")).num_faces(), 3u);
  // Nothing left of a record but repeats ("1 2 1 2"): written as it is, a facet set aside on
  // reading, not lost.
  Soup flat;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)})
    flat.add_vertex(p);
  flat.add_polygon({0, 1, 2});
  flat.add_polygon({0, 1, 0, 1});
  write_mesh(path("flat.stl"), as_mesh(flat));
  ReadInfo flat_info;
  EXPECT_EQ(read_soup(path("flat.stl"), &flat_info).num_faces(), 3u);
  EXPECT_EQ(flat_info.faces_set_aside, 2u);
}

// --- what OpenMesh's readers lose ------------------------------------------------------------

TEST_F(PlyStlIo, ply_strip_runs_of_fewer_than_3_vertices_are_counted_not_lost) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 4\nproperty list int int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 0\n6 0 0\n5 1 0\n";
  // Runs: (4 5) and (6) make no triangle; (0 1 2) one; a strip of restarts only; an empty strip.
  ReadInfo info;
  const Soup soup =
      read_soup(write("short_runs.ply", header + "7 4 5 -1 0 1 2 -1\n1 6\n2 -1 -1\n0\n"), &info);
  EXPECT_EQ(soup.num_faces(), 1u);
  EXPECT_EQ(info.declared_faces, 1u);
  EXPECT_EQ(info.empty_records, 4u);
  EXPECT_TRUE(info.changed_anything());
  // A file whose strips make no triangle at all: the error counts them.
  try {
    read_soup(write("no_triangle.ply", header + "2 0 1\n1 6\n0\n0\n"));
    FAIL() << "no error";
  } catch (const ReadError& error) {
    EXPECT_NE(std::string(error.what()).find("7 vertices, 4 records holding no face"),
              std::string::npos)
        << error.what();
  }
}

TEST_F(PlyStlIo, ply_tristrips_with_restarts_alternate_winding_and_skip_joins) {
  // Run 1: 0 1 2 3 -> (0 1 2), (2 1 3); run 2: 4 5 6 6 -> (4 5 6), (6 5 6) a join, no face.
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
      "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
      "end_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 0 0\n6 0 0\n5 1 0\n";
  const std::string file = write("strips.ply", header + vertices + "9 0 1 2 3 -1 4 5 6 6\n");
  ReadInfo info;
  const Soup soup = read_soup(file, &info);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 1, 2, 2, 1, 3, 4, 5, 6}));
  EXPECT_EQ(info.declared_faces, 3u);
  EXPECT_EQ(info.faces_kept, 3u);
  EXPECT_EQ(info.faces_set_aside, 0u);
  EXPECT_EQ(info.strip_joins, 1u);
  EXPECT_FALSE(info.changed_anything());
  EXPECT_EQ(describe_reading(info),
            "3 face records: all kept (1 degenerate strip triangle linking runs skipped)");
  EXPECT_FALSE(read_with_openmesh(file).ok && read_with_openmesh(file).soup.num_faces() > 0);
  // The same strip in big-endian binary with a uchar count and uint indices: the same soup.
  std::string binary =
      "ply\nformat binary_big_endian 1.0\nelement vertex 7\nproperty double x\n"
      "property double y\nproperty double z\nelement tristrips 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const double xyz[7][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                            {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  for (const auto& p : xyz)
    for (double x : p)
      put<double>(binary, x, true);
  put<std::uint8_t>(binary, 9);
  for (int v : {0, 1, 2, 3, -1, 4, 5, 6, 6})
    put<std::int32_t>(binary, v, true);
  ReadInfo binary_info;
  MeshAttributes attributes;
  EXPECT_TRUE(
      same_soup(read_soup(write("strips_be.ply", binary), &binary_info, &attributes), soup));
  EXPECT_EQ(binary_info.strip_joins, 1u);
  EXPECT_TRUE(attributes.double_precision);
  // A strip that joins two runs the usual way (0 1 2 3 3 4 4 5 6): two joins' worth of
  // degenerate triangles (3 3 4, 3 4 4 and 3 4 4 ... as the run goes on), only real ones kept.
  const std::string joined = write("joined.ply", header + vertices + "9 0 1 2 3 3 4 4 5 6\n");
  ReadInfo joined_info;
  const Soup joined_soup = read_soup(joined, &joined_info);
  EXPECT_EQ(joined_info.strip_joins + joined_info.declared_faces, 7u);  // 9 indices, 7 triangles
  EXPECT_EQ(joined_info.empty_records, 0u);
  EXPECT_EQ(joined_info.faces_set_aside, 0u);
  for (std::size_t f = 0; f < joined_soup.num_faces(); ++f) {
    const PolygonView p = joined_soup.polygon(f);
    EXPECT_TRUE(p[0] != p[1] && p[1] != p[2] && p[0] != p[2]) << "face " << f;
  }
  // Repair finds nothing set aside.
  const RepairResult result = repair(soup);
  EXPECT_EQ(result.mesh.soup.num_faces(), 3u);
  EXPECT_EQ(result.report.faces_set_aside, 0u);
}

TEST_F(PlyStlIo, ply_edge_elements_are_counted_as_dangling_edges) {
  const std::string file =
      write("edges.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty uchar red\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n0 3 255\n1 3 0\n");
  ReadInfo info;
  const Soup soup = read_soup(file, &info);
  EXPECT_EQ(soup.num_faces(), 1u);
  EXPECT_EQ(info.dangling_edges, 2u);
  EXPECT_EQ(info.faces_kept, 1u);
}

TEST_F(PlyStlIo, ply_unknown_elements_and_properties_are_skipped_by_their_size) {
  // Every scalar type name, lists outside the faces, an unknown element before the vertices,
  // `vertex_index` with an int count and uint entries, in both binary byte orders and ascii.
  const char* header =
      "element material 2\nproperty list uchar float weights\nproperty double shine\n"
      "element vertex 3\nproperty int8 tag\nproperty float64 x\nproperty list ushort short "
      "junk\nproperty uint16 s\nproperty float32 y\nproperty char c\nproperty int z\n"
      "element face 2\nproperty float quality\nproperty list int uint vertex_index\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  const std::string ascii_body =
      "2 0.5 0.5 7\n0 7\n"
      "-1 0 2 4 -2 9 0 99 0\n-1 1 2 4 -2 9 2 99 1\n-1 0 2 4 -2 9 2 99 3\n"
      "0.5 3 0 1 2 10 20 30\n0.5 6 0 2 1 0 1 2 40 50 60\n";
  ReadInfo info;
  MeshAttributes attributes;
  const Soup ascii =
      read_soup(write("unknown.ply", std::string("ply\nformat ascii 1.0\n") + header + ascii_body),
                &info, &attributes);
  EXPECT_EQ(ascii.positions, (std::vector<Point>{{0, 0, 0}, {1, 2, 1}, {0, 2, 3}}));
  EXPECT_EQ(ascii.corner_vertices, (std::vector<Index>{0, 1, 2, 0, 2, 1, 0, 1, 2}));
  EXPECT_EQ(ascii.face_begin, (std::vector<Index>{0, 3, 9}));
  EXPECT_EQ(info.faces_split, 1u);  // 0 2 1 0 1 2 revisits vertex 0
  ASSERT_EQ(attributes.face_colors.size(), 2u);
  EXPECT_EQ(attributes.face_colors[1], (Rgba{40, 50, 60, 255}));
  EXPECT_TRUE(attributes.vertex_colors.empty());
  EXPECT_TRUE(attributes.double_precision);  // x is float64
  for (bool big : {false, true}) {
    SCOPED_TRACE(big ? "big endian" : "little endian");
    std::string b =
        std::string("ply\nformat binary_") + (big ? "big" : "little") + "_endian 1.0\n" + header;
    for (int m = 0; m < 2; ++m) {  // material: 2 weights, or none
      put<std::uint8_t>(b, m == 0 ? 2 : 0, big);
      for (int w = 0; m == 0 && w < 2; ++w)
        put<float>(b, 0.5f, big);
      put<double>(b, 7.0, big);
    }
    const double v[3][3] = {{0, 0, 0}, {1, 2, 1}, {0, 2, 3}};
    for (int i = 0; i < 3; ++i) {
      put<std::int8_t>(b, -1, big);
      put<double>(b, v[i][0], big);
      put<std::uint16_t>(b, 2, big);
      put<std::int16_t>(b, 4, big);
      put<std::int16_t>(b, -2, big);
      put<std::uint16_t>(b, 9, big);
      put<float>(b, static_cast<float>(v[i][1]), big);
      put<std::int8_t>(b, 'c', big);
      put<std::int32_t>(b, static_cast<std::int32_t>(v[i][2]), big);
    }
    const std::vector<std::vector<std::uint32_t>> faces = {{0, 1, 2}, {0, 2, 1, 0, 1, 2}};
    for (std::size_t f = 0; f < faces.size(); ++f) {
      put<float>(b, 0.5f, big);
      put<std::int32_t>(b, static_cast<std::int32_t>(faces[f].size()), big);
      for (std::uint32_t x : faces[f])
        put<std::uint32_t>(b, x, big);
      for (std::uint8_t c : {10, 20, 30})
        put<std::uint8_t>(b, static_cast<std::uint8_t>(c + 30 * f), big);
    }
    MeshAttributes binary_attributes;
    EXPECT_TRUE(
        same_soup(read_soup(write("unknown_bin.ply", b), nullptr, &binary_attributes), ascii));
    EXPECT_EQ(binary_attributes.face_colors, attributes.face_colors);
  }
}

TEST_F(PlyStlIo, stl_facets_with_a_repeated_point_are_kept_and_set_aside) {
  // The case: a closed tetrahedron plus 6 facets that have one point three times.
  // Every facet is in `faces`, the 6 are set aside, the tetrahedron is still watertight.
  const float tet[4][9] = {{0, 0, 0, 0, 1, 0, 1, 0, 0},
                           {0, 0, 0, 0, 0, 1, 0, 1, 0},
                           {0, 0, 0, 1, 0, 0, 0, 0, 1},
                           {1, 0, 0, 0, 1, 0, 0, 0, 1}};
  std::string binary(80, ' ');
  std::string ascii = "solid t\n";
  put<std::uint32_t>(binary, 10);
  for (int t = 0; t < 10; ++t) {
    float corners[9];
    if (t < 4) {
      std::memcpy(corners, tet[t], sizeof corners);
    } else {
      for (int c = 0; c < 9; ++c)
        corners[c] = static_cast<float>(t + (c % 3));  // (t, t+1, t+2) three times
    }
    for (int i = 0; i < 3; ++i)
      put<float>(binary, 0.0f);
    ascii += "facet normal 0 0 0\n outer loop\n";
    for (int c = 0; c < 9; ++c)
      put<float>(binary, corners[c]);
    for (int c = 0; c < 3; ++c) {
      ascii += "  vertex " + std::to_string(corners[3 * c]) + " " +
               std::to_string(corners[3 * c + 1]) + " " + std::to_string(corners[3 * c + 2]) + "\n";
    }
    ascii += " endloop\nendfacet\n";
    put<std::uint16_t>(binary, 0);
  }
  ascii += "endsolid t\n";
  for (const auto& [name, bytes] :
       {std::make_pair("repeated.stl", binary), std::make_pair("repeated_ascii.stl", ascii)}) {
    SCOPED_TRACE(name);
    ReadInfo info;
    const Soup soup = read_soup(write(name, bytes), &info);
    EXPECT_EQ(soup.num_vertices(), 4u + 6u);
    EXPECT_EQ(soup.num_faces(), 10u);
    EXPECT_EQ(info.declared_faces, 10u);
    EXPECT_EQ(info.faces_kept, 4u);
    EXPECT_EQ(info.faces_set_aside, 6u);
    const RepairResult result = repair(soup);
    EXPECT_EQ(result.report.faces_set_aside, 6u);
    EXPECT_EQ(result.mesh.soup.num_faces(), 4u);
    // OpenMesh drops the 6 facets without a word (the listed difference).
    EXPECT_EQ(read_with_openmesh(path(name)).soup.num_faces(), 4u);
  }
}

// The binary reader decides a facet's normal in float where the sign is sure and in double near
// zero: over facets built to sit at every edge of that decision, the count must be the one the
// double computation gives, facet by facet.
TEST_F(PlyStlIo, binary_stl_normals_against_the_winding_are_counted_as_in_double) {
  const auto against = [](const float* n, const float* a, const float* b, const float* c) {
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double dot = n[0] * (u[1] * v[2] - u[2] * v[1]) + n[1] * (u[2] * v[0] - u[0] * v[2]) +
                       n[2] * (u[0] * v[1] - u[1] * v[0]);
    return std::isfinite(dot) && dot < 0;
  };
  std::uint64_t state = 12345;
  const auto uniform = [&state] {  // in [-1, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(std::int64_t(state >> 11) - (std::int64_t(1) << 52)) / float(1ull << 52);
  };
  std::vector<std::array<float, 12>> facets;
  for (int i = 0; i < 20000; ++i) {
    std::array<float, 12> f{};
    for (float& x : f)
      x = uniform() * (i % 7 == 0 ? 1e6f : 10.0f);
    const float w[3] = {(f[7] - f[4]) * (f[11] - f[5]) - (f[8] - f[5]) * (f[10] - f[4]),
                        (f[8] - f[5]) * (f[9] - f[3]) - (f[6] - f[3]) * (f[11] - f[5]),
                        (f[6] - f[3]) * (f[10] - f[4]) - (f[7] - f[4]) * (f[9] - f[3])};
    switch (i % 6) {
      case 0:  // a normal nearly in the facet's plane: a dot product at the rounding level
        f[0] = w[1] - w[2] + uniform() * 1e-6f * std::fabs(w[0]);
        f[1] = w[2] - w[0];
        f[2] = w[0] - w[1];
        break;
      case 1:  // a zero normal (-0 too), which makes no claim
        f[0] = -0.0f;
        f[1] = f[2] = 0.0f;
        break;
      case 2:  // a degenerate facet: three corners on a line
        for (int k = 0; k < 3; ++k)
          f[9 + k] = f[3 + k] + 2 * (f[6 + k] - f[3 + k]);
        break;
      case 3:  // huge values whose products leave float
        f[0] = 3e38f;
        f[3] = -3e38f;
        break;
      default:  // a normal along or against the winding
        for (int k = 0; k < 3; ++k)
          f[k] = (i % 2 == 0 ? 1 : -1) * w[k];
    }
    facets.push_back(f);
  }
  std::string stl(80, ' ');
  put(stl, static_cast<std::uint32_t>(facets.size()));
  std::size_t expected = 0;
  for (const auto& f : facets) {
    expected += against(f.data(), f.data() + 3, f.data() + 6, f.data() + 9);
    for (float x : f)
      put(stl, x);
    put(stl, std::uint16_t(0));
  }
  ASSERT_GT(expected, 3000u);
  const std::string file = path("normals.stl");
  std::ofstream(file, std::ios::binary) << stl;
  ReadInfo info;
  MeshAttributes attributes;
  read_soup(file, &info, &attributes);
  std::size_t counted = 0;
  for (const NotKept& n : attributes.not_kept) {
    if (n.what.rfind("STL facet normals against", 0) == 0)
      counted = n.count;
  }
  EXPECT_EQ(counted, expected);
}

TEST_F(PlyStlIo, binary_stl_whose_header_says_solid_is_read_by_its_size) {
  Soup soup = rounded_to_float(models::hourglass());
  write_mesh(path("h.stl"), as_mesh(soup));
  std::string bytes;
  {
    std::ifstream in(path("h.stl"), std::ios::binary);
    bytes.assign((std::istreambuf_iterator<char>(in)), {});
  }
  bytes.replace(0, 11, "solid hello");
  const Soup back = read_soup(write("solid.stl", bytes));
  EXPECT_EQ(back.num_faces(), soup.num_faces());
  EXPECT_TRUE(same_soup(back, read_soup(path("h.stl"))));
}

TEST_F(PlyStlIo, writers_default_to_binary_and_refuse_nothing_they_can_hold) {
  const Soup soup = models::two_cubes_sharing_edge();  // non-manifold: written as it is
  write_mesh(path("two.ply"), as_mesh(soup));
  write_mesh(path("two.stl"), as_mesh(soup));
  std::ifstream ply(path("two.ply"), std::ios::binary);
  std::string line;
  std::getline(ply, line);
  std::getline(ply, line);
  EXPECT_EQ(line, "format binary_little_endian 1.0");
  std::ifstream stl(path("two.stl"), std::ios::binary);
  char head[5];
  stl.read(head, 5);
  EXPECT_NE(std::string(head, 5), "solid");
  EXPECT_TRUE(same_soup(read_soup(path("two.ply")), soup));
  EXPECT_EQ(read_soup(path("two.stl")).num_faces(), soup.num_faces());
}
