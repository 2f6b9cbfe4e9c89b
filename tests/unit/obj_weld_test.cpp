// SPDX-License-Identifier: GPL-3.0-or-later
// An OBJ file written per face vertex, welded while it is read (core/src/io/obj_weld.h), against
// the same file read the usual way and welded after (repeated_vertices.cpp): the same file with
// " 1" (w = 1, which changes nothing) after one `v` record, which stops the weld while reading.
// Bit for bit, with 1, 2 and 3 threads (the file is read in parts), for soups it welds and for
// those it must leave to the usual route (a vertex unused or used twice, relative indices,
// triangles meeting only at vertices, an index out of range).

#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"

#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

class ObjWeld : public test_support::ScratchFolderTest {
 public:
  ObjWeld() : ScratchFolderTest("obj_weld_while_reading") {}

  //! The soup and read info of `obj` (or the error's message), read with `threads` threads.
  struct Read {
    Soup soup;
    ReadInfo info;
    std::string error;
  };
  Read read(const std::string& obj, const char* threads) {
    setenv("MESHBRIDGE_THREADS", threads, 1);
    Read r;
    try {
      r.soup = read_soup(write("soup.obj", obj), &r.info);
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    unsetenv("MESHBRIDGE_THREADS");
    return r;
  }

  //! Expects `obj` read welding (1, 2, 3 threads) as with w = 1 on its `v` record `w_at`
  //! (1 thread); returns the vertices welded.
  std::size_t expect_same_as_usual(const std::string& obj, std::size_t w_at) {
    std::string usual = obj;
    std::size_t line = 0;
    for (std::size_t at = 0; at < usual.size(); at = usual.find('\n', at) + 1) {
      if (usual.compare(at, 2, "v ") == 0 && line++ == w_at) {
        usual.insert(usual.find('\n', at), " 1");
        break;
      }
    }
    EXPECT_NE(usual, obj);
    const Read expected = read(usual, "1");
    for (const char* threads : {"1", "2", "3"}) {
      SCOPED_TRACE(std::string("threads ") + threads);
      const Read got = read(obj, threads);
      EXPECT_EQ(got.error, expected.error);
      EXPECT_EQ(got.soup.corner_vertices, expected.soup.corner_vertices);
      EXPECT_EQ(got.soup.face_begin, expected.soup.face_begin);
      EXPECT_TRUE(got.soup.positions.size() == expected.soup.positions.size() &&
                  (got.soup.positions.empty() ||
                   std::memcmp(got.soup.positions.data(), expected.soup.positions.data(),
                               got.soup.positions.size() * sizeof(Point)) == 0));
      EXPECT_EQ(got.info.vertices_welded_by_position, expected.info.vertices_welded_by_position);
      EXPECT_EQ(got.info.declared_vertices, expected.info.declared_vertices);
      EXPECT_EQ(describe_reading(got.info), describe_reading(expected.info));
    }
    return expected.info.vertices_welded_by_position;
  }
};

//! Checkerboard cubes (n per side), faces shuffled (unless `in_order`), written per face vertex
//! with coordinates of 17 digits (a file of several MB: read in parts); `relative` writes
//! "f -3 -2 -1".
std::string soup_obj(int n, bool relative, bool in_order = false) {
  const Soup shuffled = in_order ? models::checkerboard_cubes(n)
                                 : test_support::shuffled(models::checkerboard_cubes(n), 5);
  std::ostringstream obj;
  obj.precision(17);
  long corners = 0;
  for (std::size_t f = 0; f < shuffled.num_faces(); ++f) {
    const auto polygon = shuffled.polygon(f);
    for (Index v : polygon) {
      const Point& p = shuffled.positions[v];
      obj << "v " << p[0] * 0.1 + 0.01 << " " << p[1] * 0.1 + 0.01 << " " << p[2] * 0.1 + 0.01
          << "\n";
    }
    obj << "f";
    const long arity = static_cast<long>(polygon.size());
    for (long i = 0; i < arity; ++i)
      obj << " " << (relative ? i - arity : corners + i + 1);
    obj << "\n";
    corners += arity;
  }
  return obj.str();
}

TEST_F(ObjWeld, a_soup_welds_while_read_as_after_reading) {
  const std::string obj = soup_obj(15, false);
  ASSERT_GT(obj.size(), std::size_t(3) << 20);  // three parts of at least 1 MiB
  const std::size_t welded = expect_same_as_usual(obj, 0);
  EXPECT_GT(welded, 0u);
  EXPECT_EQ(expect_same_as_usual(obj, 12345), welded);  // the weld stopped in the middle
  const Read one = read(obj, "1");
  EXPECT_EQ(one.soup.num_vertices() + welded, 3 * one.soup.num_faces());
}

// In the model's face order most positions of a part are new to the parts before it: appending
// the parts inserts them (prefetched ahead, the table growing where it must).
TEST_F(ObjWeld, a_soup_in_face_order_welds_as_after_reading) {
  const std::string obj = soup_obj(15, false, true);
  ASSERT_GT(obj.size(), std::size_t(3) << 20);
  const std::size_t welded = expect_same_as_usual(obj, 0);
  EXPECT_GT(welded, 0u);
  EXPECT_EQ(expect_same_as_usual(obj, 54321), welded);
}

TEST_F(ObjWeld, relative_indices_weld_across_parts) {
  const std::string obj = soup_obj(15, true);
  EXPECT_GT(expect_same_as_usual(obj, 0), 0u);
}

TEST_F(ObjWeld, files_it_must_not_weld_read_as_usual) {
  const std::string soup = soup_obj(3, false);
  // A vertex no face uses (last), a vertex used twice, a corner past the last vertex.
  EXPECT_GT(expect_same_as_usual(soup + "v 5 5 5\n", 3), 0u);
  EXPECT_EQ(expect_same_as_usual(soup + "f 1 5 9\n", 3), 0u);
  EXPECT_EQ(expect_same_as_usual(soup + "v 1 2 3\nv 2 3 4\nf 1 9999 9998\n", 3), 0u);
  // Triangles that meet only at vertices (a repaired bowtie): left as written.
  const std::string bowtie =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0\nv -1 0 0\nv 0 -1 0\nf 1 2 3\nf 4 5 6\n";
  EXPECT_EQ(expect_same_as_usual(bowtie, 5), 0u);
  EXPECT_EQ(read(bowtie, "1").soup.num_vertices(), 6u);
}

}  // namespace
}  // namespace meshbridge
