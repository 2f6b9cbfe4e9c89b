// SPDX-License-Identifier: GPL-3.0-or-later
// The hostile-input catalogue: files and soups built to break readers and algorithms. Each case
// expects a clear error (ReadError or InvalidSoupError whose message names the problem) or a
// correct result (every repair invariant holds) - never a crash, a hang, a huge allocation or a
// partial result.
//
// Every file is first read in a forked child process with an address-space limit and an alarm,
// so a crash, a hang or a huge allocation inside a reader is reported as a test failure instead
// of taking the test binary down; the parent then repeats the read to check the result.
#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/validate.h"

#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define MESHBRIDGE_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESHBRIDGE_TEST_ASAN 1
#endif
#endif

using namespace meshbridge;
using meshbridge::test_support::expect_repair_invariants;

namespace {

//! What happened to one read in the sandbox.
struct Outcome {
  enum Kind { read, read_error, invalid_soup, other_exception, out_of_memory, crashed, timed_out };
  Kind kind = crashed;
  std::string message;
  std::size_t vertices = 0, faces = 0;
};

std::ostream& operator<<(std::ostream& os, const Outcome& o) {
  static const char* names[] = {"read",          "ReadError", "InvalidSoupError", "other exception",
                                "out of memory", "crashed",   "timed out"};
  return os << names[o.kind] << " (" << o.vertices << " vertices, " << o.faces
            << " faces): " << o.message;
}

// Address space the child may use beyond what it already has: far more than any of these tiny
// files needs, far less than what a header's claimed counts would take.
constexpr std::size_t kMemoryHeadroom = std::size_t(256) << 20;
constexpr unsigned kSecondsPerRead = 20;

std::size_t current_address_space() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

//! Reads `path` with read_soup in a child process that has a memory limit and an alarm.
Outcome read_in_sandbox(const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0)
    return {Outcome::crashed, "pipe failed"};
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0)
    return {Outcome::crashed, "fork failed"};
  if (child == 0) {
    close(fds[0]);
#ifndef MESHBRIDGE_TEST_ASAN  // ASan reserves terabytes of address space up front
    const rlimit limit{current_address_space() + kMemoryHeadroom,
                       current_address_space() + kMemoryHeadroom};
    setrlimit(RLIMIT_AS, &limit);
#endif
    alarm(kSecondsPerRead);
    Outcome o;
    try {
      const Soup soup = read_soup(path);
      o = {Outcome::read, "", soup.num_vertices(), soup.num_faces()};
    } catch (const ReadError& e) {
      o = {Outcome::read_error, e.what()};
    } catch (const InvalidSoupError& e) {
      o = {Outcome::invalid_soup, e.what()};
    } catch (const std::bad_alloc&) {
      o = {Outcome::out_of_memory, "std::bad_alloc"};
    } catch (const std::exception& e) {
      o = {Outcome::other_exception, e.what()};
    }
    std::ostringstream text;
    text << o.kind << ' ' << o.vertices << ' ' << o.faces << ' ' << o.message;
    const std::string bytes = text.str();
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = write(fds[1], bytes.data() + done, bytes.size() - done);
      if (n <= 0)
        break;
      done += static_cast<std::size_t>(n);
    }
    _exit(0);
  }
  close(fds[1]);
  std::string bytes;
  char buffer[4096];
  ssize_t n;
  while ((n = read(fds[0], buffer, sizeof buffer)) > 0)
    bytes.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  Outcome o;
  if (WIFSIGNALED(status)) {
    o.kind = WTERMSIG(status) == SIGALRM ? Outcome::timed_out : Outcome::crashed;
    o.message = std::string("signal ") + strsignal(WTERMSIG(status));
    return o;
  }
  std::istringstream text(bytes);
  int kind = Outcome::crashed;
  text >> kind >> o.vertices >> o.faces;
  o.kind = static_cast<Outcome::Kind>(kind);
  std::getline(text >> std::ws, o.message);
  if (bytes.empty())
    o.message = "child exited without a result";
  return o;
}

class HostileFile : public test_support::ScratchFolderTest {
 protected:
  HostileFile() : ScratchFolderTest("hostile") {}

  //! The file must be rejected with an exception of type E whose message contains `expected`.
  template <class E>
  void expect_error(const std::string& name, const std::string& bytes,
                    const std::string& expected) {
    SCOPED_TRACE(name);
    const std::string path = write(name, bytes);
    const Outcome o = read_in_sandbox(path);
    const Outcome::Kind kind =
        std::is_same<E, ReadError>::value ? Outcome::read_error : Outcome::invalid_soup;
    EXPECT_EQ(o.kind, kind) << o;
    EXPECT_NE(o.message.find(expected), std::string::npos) << o;
    EXPECT_NE(o.message.find(path), std::string::npos) << "message does not name the file: " << o;
    if (o.kind == kind)
      EXPECT_THROW(read_soup(path), E);
  }

  //! The file must read, with these counts, and repair with every invariant holding.
  Soup expect_read(const std::string& name, const std::string& bytes, std::size_t vertices,
                   std::size_t faces, ReadInfo* info = nullptr) {
    SCOPED_TRACE(name);
    const std::string path = write(name, bytes);
    const Outcome o = read_in_sandbox(path);
    EXPECT_EQ(o.kind, Outcome::read) << o;
    if (o.kind != Outcome::read)
      return {};
    const Soup soup = read_soup(path, info);
    EXPECT_EQ(soup.num_vertices(), vertices);
    EXPECT_EQ(soup.num_faces(), faces);
    expect_repair_invariants(soup, repair(soup));
    return soup;
  }
};

// Little-endian binary helpers.
template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

//! A binary STL with `triangles` (9 floats each) whose header claims `claimed` triangles.
std::string binary_stl(const std::vector<std::vector<float>>& triangles, std::uint32_t claimed,
                       const std::string& header_text = "binary stl") {
  std::string out = header_text;
  out.resize(80, ' ');
  put<std::uint32_t>(out, claimed);
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i)
      put<float>(out, 0.0f);  // normal
    for (float x : t)
      put<float>(out, x);
    put<std::uint16_t>(out, 0);
  }
  return out;
}

const std::vector<std::vector<float>> kTetrahedron = {
    {0, 0, 0, 0, 1, 0, 1, 0, 0},
    {0, 0, 0, 0, 0, 1, 0, 1, 0},
    {0, 0, 0, 1, 0, 0, 0, 0, 1},
    {1, 0, 0, 0, 1, 0, 0, 0, 1},
};

//! Binary little-endian PLY header with float x y z and a `list uchar int` face property.
std::string binary_ply_header(const std::string& vertex_count, const std::string& face_count,
                              const std::string& list = "list uchar int") {
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + vertex_count +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + face_count +
         "\nproperty " + list + " vertex_indices\nend_header\n";
}

//! Vertex and face records of a tetrahedron for binary_ply_header("4", "4").
std::string binary_ply_tetrahedron_body() {
  std::string out;
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : v)
    for (float x : p)
      put<float>(out, x);
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : f) {
    put<std::uint8_t>(out, 3);
    for (int i : t)
      put<std::int32_t>(out, i);
  }
  return out;
}

const char* kObjTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

const char* kOffTetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

}  // namespace

// --- the catalogue: files -------------------------------------------------------------------

TEST_F(HostileFile, empty_file_of_every_format) {
  for (const char* ext : {"obj", "off", "ply", "stl", "OBJ"})
    expect_error<ReadError>(std::string("empty.") + ext, "", "file is empty");
}

TEST_F(HostileFile, obj_with_only_comments_and_blank_lines) {
  expect_error<ReadError>("comments.obj", "# nothing\n\n   \n# here\n", "no polygons");
}

TEST_F(HostileFile, obj_vertices_without_faces) {
  expect_error<ReadError>("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no polygons");
}

TEST_F(HostileFile, obj_index_out_of_range) {
  // Named by its line (a face may refer to a vertex written after it: checked after the read).
  expect_error<ReadError>("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# \\\nf 1 2 4\n",
                          "line 6: face corner 3 refers to vertex 4, but the file has 3 vertices");
  expect_error<ReadError>("range_continued.obj",
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\nf 1 \\\n 2 \\\n 9\nv 0 0 1\n",
                          "line 7: face corner 3 refers to vertex 9, but the file has 4 vertices");
}

TEST_F(HostileFile, obj_index_zero_and_relative_index_before_the_first_vertex) {
  expect_error<ReadError>("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
                          "line 4: face corner '0': OBJ indices start at 1");
  expect_error<ReadError>(
      "relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n",
      "line 4: face corner '-7' counts 7 vertices back, before the first vertex: "
      "only 3 vertices come before it");
}

TEST_F(HostileFile, obj_index_too_large_for_any_integer) {
  // An index no integer holds is named; one that fits is out of range for this soup.
  expect_error<ReadError>("huge_index.obj",
                          "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n",
                          "line 4: face corner '99999999999999999999999' is not an index");
  expect_error<ReadError>("int_max.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n",
                          "line 4: face corner 3 refers to vertex 2147483648, but the file has 3");
}

TEST_F(HostileFile, obj_nan_coordinate) {
  expect_error<InvalidSoupError>("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n",
                                 "line 2: vertex 2 has a non-finite coordinate");
}

TEST_F(HostileFile, obj_infinite_and_overflowing_coordinates) {
  expect_error<InvalidSoupError>("inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n",
                                 "line 2: vertex 2 has a non-finite coordinate");
  expect_error<ReadError>("overflow.obj", "v 0 0 0\nv 1 1e999 0\nv 0 1 0\nf 1 2 3\n",
                          "line 2: vertex 2: '1e999' is not a number a double can hold");
}

TEST_F(HostileFile, obj_faces_with_zero_one_and_two_vertices_are_set_aside) {
  // "f 1" and "f 1 2" stay in the soup as triangles repeating their last corner (set aside by
  // repair, listed by check); "f" alone has nothing to keep and is only counted.
  ReadInfo info;
  const Soup soup = expect_read("short_faces.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1\nf 1 2\nf\nf 1 2 3\n", 3, 3, &info);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 0, 0, 0, 1, 1, 0, 1, 2}));
  EXPECT_EQ(info.declared_faces, 4u);
  EXPECT_EQ(info.faces_set_aside, 3u);
  EXPECT_EQ(info.faces_without_corners, 1u);
  EXPECT_EQ(info.faces_kept, 1u);
}

TEST_F(HostileFile, obj_with_non_utf8_bytes) {
  std::string bytes = "# \xff\xfe\xc3\x28 latin-1: \xe9\xe8\n";
  bytes += "o \xff\xfe\xfd\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  bytes += "g \x80\x81\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  expect_read("non_utf8.obj", bytes, 4, 4);
}

TEST_F(HostileFile, obj_with_nul_bytes_and_binary_garbage) {
  std::string bytes = kObjTetrahedron;
  bytes.insert(10, std::string("\0\0\0", 3));
  expect_error<ReadError>("nul.obj", bytes, "line 2: vertex 2: '???1' is not a number");
  std::string garbage;
  for (int i = 0; i < 4096; ++i)
    garbage.push_back(static_cast<char>((i * 7919) % 256));
  expect_error<ReadError>("garbage.obj", garbage, "no polygons");
}

TEST_F(HostileFile, obj_with_a_very_long_line) {
  std::string bytes = "# " + std::string(8 << 20, 'x') + "\n" + kObjTetrahedron;
  expect_read("long_line.obj", bytes, 4, 4);
}

TEST_F(HostileFile, obj_polygon_with_a_repeated_vertex_is_read_as_written) {
  // The soup keeps the repeated corner (repair collapses it); the record counts as kept.
  ReadInfo info;
  const Soup soup =
      expect_read("repeat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2 3\n", 3, 1, &info);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 1, 1, 2}));
  EXPECT_EQ(info.faces_kept, 1u);
}

TEST_F(HostileFile, obj_face_corner_without_a_vertex_index) {
  // Found by fuzz_read: OpenMesh's OBJ reader asserts (aborts) on a texture coordinate before
  // any vertex index of a face.
  expect_error<ReadError>("slash.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf /1 2 3\n",
                          "line 5: face corner '/1' has no vertex index");
  expect_error<ReadError>("slash_texcoord.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf x /1/1 2 3\n",
                          "face corner 'x' has no vertex index");
  // A corner without its vertex is an error too: dropping it would change the polygon.
  expect_error<ReadError>("slash_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf //1 1 2 3\n",
                          "line 4: face corner '//1' has no vertex index");
  expect_read("texcoords.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n", 3, 1);
}

TEST_F(HostileFile, obj_material_library_naming_an_endless_file) {
  // OpenMesh opens the file an mtllib record names, relative to the OBJ: /dev/zero never ends.
  // read_soup hands OpenMesh the OBJ without its mtllib records.
  expect_read("endless_material.obj",
              "mtllib ../../../../../../../../../../dev/zero\n" + std::string(kObjTetrahedron), 4,
              4);
  expect_read("indented_material.obj",
              "  mtllib\t../../../../../../../../../../dev/zero\r\n" + std::string(kObjTetrahedron),
              4, 4);
}

TEST_F(HostileFile, off_header_claims_more_vertices_than_present) {
  expect_error<ReadError>("few_vertices.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "OFF vertex 5 of 5: expected 3 numbers, but the file ends");
}

TEST_F(HostileFile, off_header_claims_more_faces_than_present) {
  expect_error<ReadError>("few_faces.off", "OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "OFF face 2 of 4 is missing");
}

TEST_F(HostileFile, off_negative_counts) {
  expect_error<ReadError>("negative.off", "OFF\n-3 -1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "declares -3 vertices and -1 faces: a count cannot be negative");
  expect_error<ReadError>("negative_faces.off", "OFF\n3 -1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "declares 3 vertices and -1 faces: a count cannot be negative");
}

TEST_F(HostileFile, off_huge_counts_claiming_gigabytes) {
  expect_error<ReadError>("huge.off", "OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n",
                          "declares 4000000000 vertices and 4000000000 faces, more than");
  expect_error<ReadError>("huge_faces.off", "OFF\n3 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "2000000000 faces, more than a file of 45 bytes can hold");
}

TEST_F(HostileFile, off_face_with_a_huge_arity) {
  expect_error<ReadError>("arity.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n",
                          "OFF face 1 claims 4000000000 corners");
  expect_error<ReadError>("arity_neg.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
                          "OFF face 1 has a negative corner count -3 (line 6)");
}

TEST_F(HostileFile, off_faces_with_zero_one_and_two_vertices) {
  // As in OBJ: set aside (1 or 2 corners stay as padded triangles, 0 corners only counted).
  ReadInfo info;
  const Soup soup = expect_read(
      "short.off", "OFF\n3 4 0\n0 0 0\n1 0 0\n0 1 0\n0\n1 0\n2 0 1\n3 0 1 2\n", 3, 3, &info);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 0, 0, 0, 1, 1, 0, 1, 2}));
  EXPECT_EQ(info.declared_faces, 4u);
  EXPECT_EQ(info.faces_set_aside, 3u);
  EXPECT_EQ(info.faces_without_corners, 1u);
  EXPECT_EQ(info.faces_kept, 1u);
}

TEST_F(HostileFile, off_index_out_of_range_and_negative) {
  expect_error<ReadError>("range.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n",
                          "OFF face 2 refers to vertex index 3 (line 7), but the file has 3 "
                          "vertices (OFF counts from 0)");
  expect_error<ReadError>("negative_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
                          "face 1 refers to vertex index -1");
}

TEST_F(HostileFile, off_truncated_binary) {
  std::string bytes = "OFF BINARY\n";
  for (std::int32_t n : {4, 4, 0})
    put<std::int32_t>(bytes, n);
  put<float>(bytes, 0.0f);  // then nothing
  expect_error<ReadError>("truncated_binary.off", bytes,
                          "binary OFF declares 4 vertices (48 bytes) but only 4 bytes follow");
  std::string faces = "OFF BINARY\n";
  for (std::int32_t n : {3, 1, 0})
    put<std::int32_t>(faces, n);
  for (int i = 0; i < 9; ++i)
    put<float>(faces, float(i % 2));
  put<std::int32_t>(faces, 2000000000);  // a face claiming 2 * 10^9 corners
  expect_error<ReadError>("huge_arity_binary.off", faces,
                          "binary OFF face 1 claims 2000000000 corners");
}

TEST_F(HostileFile, ply_ascii_header_claims_more_elements_than_present) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n";
  expect_error<ReadError>("few.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "ascii PLY: line 13, vertex 4 of 5: 4 values where the header's "
                          "properties (x, y, z) take 3 (a malformed line, or a false element "
                          "count before it)");
}

TEST_F(HostileFile, ply_negative_element_count) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nproperty float y\n"
      "property float z\nelement face -1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_error<ReadError>("negative.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "PLY element 'vertex' has count '-3', not a non-negative integer");
}

TEST_F(HostileFile, ply_two_gigabyte_claimed_allocation_in_the_header) {
  expect_error<ReadError>(
      "claims_2gb.ply",
      binary_ply_header("2147483647", "2147483647") + binary_ply_tetrahedron_body(),
      "2147483647 items of 12 bytes need 25769803764 bytes, 100 remain");
  expect_error<ReadError>("claims_4g.ply",
                          binary_ply_header("4294967295", "4") + binary_ply_tetrahedron_body(),
                          "4294967295 items of 12 bytes need");
  expect_error<ReadError>("claims_2g_faces.ply",
                          binary_ply_header("4", "2147483647") + binary_ply_tetrahedron_body(),
                          "binary PLY declares 2147483647 faces, more than the 52 bytes");
}

TEST_F(HostileFile, ply_binary_tetrahedron_reads_and_truncated_binary_ply_is_rejected) {
  const std::string whole = binary_ply_header("4", "4") + binary_ply_tetrahedron_body();
  expect_read("whole.ply", whole, 4, 4);
  const std::size_t header = binary_ply_header("4", "4").size();
  expect_error<ReadError>("cut_in_vertices.ply", whole.substr(0, header + 20),
                          "binary PLY ends inside element 'vertex': 4 items of 12 bytes");
  expect_error<ReadError>("cut_in_faces.ply", whole.substr(0, whole.size() - 7),
                          "PLY face 4 of 4 claims 3 corners, more than the rest of the file holds");
}

TEST_F(HostileFile, ply_binary_list_with_a_huge_count) {
  std::string bytes = binary_ply_header("4", "1", "list uint int");
  const std::string body = binary_ply_tetrahedron_body();
  bytes += body.substr(0, 48);  // the four vertices
  put<std::uint32_t>(bytes, 0xFFFFFFFFu);
  put<std::int32_t>(bytes, 0);
  expect_error<ReadError>("huge_list_uint.ply", bytes,
                          "PLY face 1 of 1 claims 4294967295 corners, more than the rest");
  std::string as_int = binary_ply_header("4", "1", "list int int") + body.substr(0, 48);
  put<std::int32_t>(as_int, -1);  // read as 4294967295 corners
  put<std::int32_t>(as_int, 0);
  expect_error<ReadError>("huge_list_int.ply", as_int,
                          "PLY face 1 of 1 has a negative corner count (-1)");
}

TEST_F(HostileFile, ply_faces_with_zero_one_and_two_vertices_are_set_aside) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  // As in OBJ and OFF: set aside (1 or 2 corners stay as padded triangles, 0 only counted).
  ReadInfo info;
  const Soup soup = expect_read(
      "short.ply", header + "0 0 0\n1 0 0\n0 1 0\n0\n1 0\n2 0 1\n3 0 1 2\n", 3, 3, &info);
  EXPECT_EQ(soup.corner_vertices, (std::vector<Index>{0, 0, 0, 0, 1, 1, 0, 1, 2}));
  EXPECT_EQ(info.declared_faces, 4u);
  EXPECT_EQ(info.faces_set_aside, 3u);
  EXPECT_EQ(info.faces_without_corners, 1u);
  EXPECT_EQ(info.faces_kept, 1u);
}

TEST_F(HostileFile, ply_negative_and_out_of_range_indices) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_error<ReadError>("negative_index.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -5\n",
                          "PLY face 1 (line 13) refers to vertex index -5");
  expect_error<ReadError>("range.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
                          "PLY face 1 (line 13) refers to vertex index 3, but the file has 3 "
                          "vertices (indices count from 0)");
}

TEST_F(HostileFile, binary_ply_negative_index_is_named_as_written) {
  // The int32 index -5 in a binary file (the fast face path), and a short (the general one).
  for (const char* type : {"int", "short"}) {
    std::string file = std::string("ply\nformat binary_little_endian 1.0\nelement vertex 3\n") +
                       "property float x\nproperty float y\nproperty float z\nelement face 1\n" +
                       "property list uchar " + type + " vertex_indices\nend_header\n";
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    file.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    file.push_back(3);
    const int width = std::string(type) == "int" ? 4 : 2;
    for (const std::int32_t index : {0, 1, -5})  // little endian: the low bytes come first
      file.append(reinterpret_cast<const char*>(&index), std::size_t(width));
    expect_error<ReadError>(std::string("negative_") + type + ".ply", file,
                            "face 1 refers to vertex index -5");
  }
}

TEST_F(HostileFile, ply_header_without_end_or_with_unknown_format) {
  // Without end_header OpenMesh's header parser loops forever.
  expect_error<ReadError>("no_end.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n0 0 0\n",
                          "no end_header");
  expect_error<ReadError>("bad_version.ply",
                          "ply\nformat ascii one\nelement vertex 3\nend_header\n0 0 0\n",
                          "unsupported PLY version 'one' (expected 1.0)");
  // A property before any element makes OpenMesh use elements_.back() of an empty vector.
  expect_error<ReadError>("property_first.ply",
                          "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\n"
                          "end_header\n0\n",
                          "property before any element");
  expect_error<ReadError>("bad_format.ply",
                          "ply\nformat zigzag 9.9\nelement vertex 3\nproperty float x\n"
                          "end_header\n0\n1\n2\n",
                          "Unsupported PLY format: zigzag");
  expect_error<ReadError>("bad_type.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty quaternion x\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0\n1\n2\n3 0 1 2\n",
                          "PLY property 'x' of element 'vertex' has unknown type 'quaternion'");
  expect_error<ReadError>("float_indices.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement face 1\n"
                          "property list uchar float vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "is a list of 'float', not of integers");
  expect_error<ReadError>("empty_element.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\nelement junk 4000000000\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                          "element 'junk' declares 4000000000 items without any property");
}

// Fuzz finding (fuzz_read, CI run of 2026-11-22): OpenMesh's binary PLY reader does not check the
// vertex dimension, so a vertex element without properties made it add 10^8 vertices out of no
// bytes at all (a 1.5 GiB allocation). Both encodings now get the same clear error.
TEST_F(HostileFile, ply_vertex_element_without_coordinates) {
  expect_error<ReadError>(
      "no_properties_binary.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\n"
      "end_header\n",
      "the PLY vertex element has no 'x', 'y', 'z' property (a vertex needs x, y and z)");
  expect_error<ReadError>(
      "no_properties_ascii.ply",
      "ply\nformat ascii 1.0\nelement vertex 100000000\nelement face 0\n"
      "end_header\n",
      "the PLY vertex element has no 'x', 'y', 'z' property (a vertex needs x, y and z)");
  expect_error<ReadError>(
      "only_x_binary.ply",
      "ply\nformat binary_big_endian 1.0\nelement vertex 2000000000\n"
      "property float x\nend_header\n",
      "the PLY vertex element has no 'y', 'z' property (a vertex needs x, y and z)");
  expect_error<ReadError>("twice_x.ply",
                          "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                          "property float x\nproperty float y\nproperty float z\nend_header\n"
                          "0 0 0 0\n",
                          "PLY header line 5: PLY element 'vertex' has property 'x' twice");
}

TEST_F(HostileFile, binary_stl_reads_a_tetrahedron_welded) {
  expect_read("tetrahedron.stl", binary_stl(kTetrahedron, 4), 4, 4);
}

TEST_F(HostileFile, binary_stl_whose_size_disagrees_with_its_count) {
  // Whole facets after a header count that disagrees (too large, too small, 4 billion): the
  // facets the file holds are read, as admesh and slicers read them, and the count is named.
  for (const std::uint32_t count : {5u, 3u, 0xFFFFFFFFu}) {
    MeshAttributes attributes;
    const std::string name = "count_" + std::to_string(count) + ".stl";
    EXPECT_EQ(
        read_soup(write(name, binary_stl(kTetrahedron, count)), nullptr, &attributes).num_faces(),
        4u);
    ASSERT_EQ(attributes.not_kept.size(), 1u) << name;
    EXPECT_EQ(attributes.not_kept[0].what, "binary STL header that counts " +
                                               std::to_string(count) +
                                               " triangles before 4 whole facets, all read");
    EXPECT_TRUE(attributes.not_kept[0].fault);
  }
  // A file cut inside a facet is no whole binary STL: an error that says it may be truncated.
  std::string cut = binary_stl(kTetrahedron, 4);
  cut.resize(cut.size() - 20);
  expect_error<ReadError>("cut.stl", cut,
                          "header counts 4 triangles has 284 bytes, this file has 264 (3 whole "
                          "facets: a truncated file?)");
}

TEST_F(HostileFile, binary_stl_with_zero_triangles_or_only_a_header) {
  expect_error<ReadError>("zero.stl", binary_stl({}, 0), "no polygons");
  expect_error<ReadError>("header_only.stl", std::string(80, 'x'), "at least 84 bytes");
}

TEST_F(HostileFile, binary_stl_with_nan_and_infinite_coordinates) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  auto triangles = kTetrahedron;
  triangles[1][4] = nan;
  // OpenMesh would weld the NaN corner onto an arbitrary vertex (NaN compares equal to all).
  expect_error<InvalidSoupError>("nan.stl", binary_stl(triangles, 4),
                                 "binary STL facet 2, corner 2 has a non-finite coordinate");
  triangles = kTetrahedron;
  triangles[2][0] = inf;
  expect_error<InvalidSoupError>("inf.stl", binary_stl(triangles, 4),
                                 "binary STL facet 3, corner 1 has a non-finite coordinate");
}

TEST_F(HostileFile, binary_stl_whose_header_starts_with_solid) {
  expect_read("solid_header.stl", binary_stl(kTetrahedron, 4, "solid but actually binary"), 4, 4);
}

TEST_F(HostileFile, binary_stl_with_triangles_collapsed_to_a_point_are_set_aside) {
  // A facet whose corners weld together stays in the soup (repair sets it aside) and counts in
  // faces_set_aside: every facet of the file is accounted for.
  const std::vector<std::vector<float>> points(3, std::vector<float>(9, 1.5f));
  ReadInfo info;
  expect_read("points.stl", binary_stl(points, 3), 1, 3, &info);
  EXPECT_EQ(info.declared_faces, 3u);
  EXPECT_EQ(info.faces_set_aside, 3u);
  EXPECT_EQ(info.faces_kept, 0u);
  auto triangles = kTetrahedron;
  triangles.push_back(std::vector<float>(9, 0.0f));
  expect_read("one_collapsed.stl", binary_stl(triangles, 5), 4, 5, &info);
  EXPECT_EQ(info.declared_faces, 5u);
  EXPECT_EQ(info.faces_kept, 4u);
  EXPECT_EQ(info.faces_set_aside, 1u);
}

TEST_F(HostileFile, ascii_stl_truncated_and_malformed) {
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
      " endloop\nendfacet\n";
  expect_read("one.stl", "solid t\n" + facet + "endsolid t\n", 3, 1);
  expect_error<ReadError>("truncated.stl", "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0",
                          "ASCII STL line 4: facet 1, corner 1 is not 'vertex x y z'");
  expect_error<ReadError>("two_vertices.stl",
                          "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n"
                          "  vertex 1 0 0\n endloop\nendfacet\nendsolid t\n",
                          "ASCII STL line 2: facet 1 has 2 vertices; an STL facet is a triangle");
  expect_error<ReadError>("nan.stl",
                          "solid t\nfacet normal 0 0 1\n outer loop\n  vertex nan 0 0\n"
                          "  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\nendsolid t\n",
                          "ASCII STL line 4: facet 1, corner 1 is not");
}

TEST_F(HostileFile, unknown_extension_directory_and_missing_file) {
  expect_error<ReadError>("mesh.dxf", kObjTetrahedron, "unknown format");
  expect_error<ReadError>("noextension", kObjTetrahedron, "unknown format");
  const std::string sub = dir_ + "/folder.obj";
  ASSERT_EQ(mkdir(sub.c_str(), 0700), 0);
  EXPECT_EQ(read_in_sandbox(sub).kind, Outcome::read_error);
  EXPECT_THROW(read_soup(sub), ReadError);
  rmdir(sub.c_str());
  EXPECT_THROW(read_soup(dir_ + "/missing.obj"), ReadError);
}

TEST_F(HostileFile, format_and_extension_disagree) {
  expect_error<ReadError>("off_inside.obj", kOffTetrahedron, "no polygons");
  expect_error<ReadError>("obj_inside.off", kObjTetrahedron, "not an OFF file: it starts with 'v'");
  expect_error<ReadError>("obj_inside.ply", kObjTetrahedron,
                          "not a PLY file: it starts with 'v', not 'ply'");
  expect_error<ReadError>("obj_inside.stl", kObjTetrahedron, "neither ASCII STL");
}

// The checks that guard OpenMesh's readers must not refuse what they read correctly.
TEST_F(HostileFile, valid_variants_of_every_format_still_read) {
  expect_read("tetrahedron.obj", kObjTetrahedron, 4, 4);
  expect_read("tetrahedron.off", kOffTetrahedron, 4, 4);
  expect_read("colors.off",
              "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n"
              "0 0 1 9 9 9 255\n3 0 2 1 255 0 0\n3 0 1 3 0 255 0\n3 0 3 2 1 1 1\n"
              "3 1 2 3 7 7 7\n",
              4, 4);
  expect_read("normals.off",
              "NOFF\n4 4 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n0 0 1 0 0 1\n"
              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
              4, 4);
  expect_read("crlf.off",
              "OFF\r\n4 4 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 2 1\r\n"
              "3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n",
              4, 4);
  std::string binary_off = "OFF BINARY\n";
  for (std::int32_t n : {4, 1, 0})
    put<std::int32_t>(binary_off, n);
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f})
    put<float>(binary_off, x);
  for (std::int32_t n : {4, 0, 1, 2, 3})
    put<std::int32_t>(binary_off, n);
  expect_read("binary.off", binary_off, 4, 1);
  expect_read("crlf.ply",
              "ply\r\nformat ascii 1.0\r\ncomment hi\r\nelement vertex 4\r\nproperty float x\r\n"
              "property float y\r\nproperty float z\r\nproperty float nx\r\nproperty float ny\r\n"
              "property float nz\r\nproperty uchar red\r\nproperty uchar green\r\n"
              "property uchar blue\r\nelement face 4\r\nproperty list uchar int vertex_indices\r\n"
              "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\nend_header\r\n"
              "0 0 0 0 0 1 1 2 3\r\n1 0 0 0 0 1 1 2 3\r\n0 1 0 0 0 1 1 2 3\r\n"
              "0 0 1 0 0 1 1 2 3\r\n3 0 2 1 1 2 3\r\n3 0 1 3 1 2 3\r\n3 0 3 2 1 2 3\r\n"
              "3 1 2 3 1 2 3\r\n",
              4, 4);
  // Big-endian, double coordinates, a colour, 16-bit corner counts, a per-face float and an
  // element after the faces.
  std::string big_endian =
      "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\n"
      "property double y\nproperty double z\nproperty uchar red\nelement face 4\n"
      "property list uint16 uint vertex_indices\nproperty float quality\nelement edge 1\n"
      "property int vertex1\nproperty int vertex2\nend_header\n";
  const auto put_big = [&](auto value) {
    char bytes[sizeof(value)];
    std::memcpy(bytes, &value, sizeof(value));
    std::reverse(bytes, bytes + sizeof(value));
    big_endian.append(bytes, sizeof(value));
  };
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : corners) {
    for (double x : p)
      put_big(x);
    put_big(std::uint8_t(7));
  }
  const std::uint32_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    put_big(std::uint16_t(3));
    for (std::uint32_t i : f)
      put_big(i);
    put_big(0.5f);
  }
  put_big(std::int32_t(0));
  put_big(std::int32_t(1));
  expect_read("big_endian.ply", big_endian, 4, 4);
  std::string ascii_stl = "solid t\r\n";
  for (const auto& t : kTetrahedron) {
    ascii_stl += "  facet normal 0 0 0\r\n    outer loop\r\n";
    for (int c = 0; c < 3; ++c) {
      ascii_stl += "      vertex " + std::to_string(t[3 * c]) + " " + std::to_string(t[3 * c + 1]) +
                   " " + std::to_string(t[3 * c + 2]) + "\r\n";
    }
    ascii_stl += "    endloop\r\n  endfacet\r\n";
  }
  expect_read("crlf.stl", ascii_stl + "endsolid t\r\n", 4, 4);
}

// --- the catalogue: soups -------------------------------------------------------------------

namespace {

using test_support::triangle;

//! validate_soup, detect_defects and repair must all throw InvalidSoupError naming `expected`.
void expect_invalid(const Soup& soup, const std::string& expected) {
  for (int entry = 0; entry < 3; ++entry) {
    SCOPED_TRACE(entry);
    try {
      if (entry == 0)
        validate_soup(soup);
      else if (entry == 1)
        detect_defects(soup);
      else
        repair(soup);
      ADD_FAILURE() << "no InvalidSoupError";
    } catch (const InvalidSoupError& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  }
}

// Processor time used by this process so far, in seconds: wall time would fail these tests on
// a loaded machine (other tests and builds sharing the cores), processor time does not.
double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double seconds_since(double start) {
  return cpu_seconds() - start;
}

// These limits catch a quadratic blow-up (minutes), not speed; a sanitizer build runs several
// times slower, and scripts/test_sanitizers.sh says how much through MESHBRIDGE_TIME_SCALE.
double time_limit(double seconds) {
  const char* scale = std::getenv("MESHBRIDGE_TIME_SCALE");
  return seconds * (scale != nullptr && std::atof(scale) >= 1.0 ? std::atof(scale) : 1.0);
}

}  // namespace

TEST(HostileSoup, polygons_with_zero_one_and_two_corners) {
  for (std::size_t arity : {0u, 1u, 2u}) {
    Soup soup = triangle();
    soup.add_polygon(std::vector<Index>(arity, 1));
    expect_invalid(soup, "face 1 has " + std::to_string(arity) + " corner(s)");
  }
}

TEST(HostileSoup, index_out_of_range_and_the_no_index_marker) {
  Soup soup = triangle();
  soup.add_polygon({0, 1, 3});
  expect_invalid(soup, "vertex index 3 is out of range");
  Soup marker = triangle();
  marker.add_polygon({0, 1, kNoIndex});
  expect_invalid(marker, "vertex index 4294967295 is out of range");
}

TEST(HostileSoup, nan_and_infinite_coordinates) {
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    Soup soup = triangle();
    soup.positions[2][1] = bad;
    expect_invalid(soup, "vertex 2 has a non-finite coordinate");
  }
}

TEST(HostileSoup, broken_face_offsets) {
  Soup soup = triangle();
  soup.face_begin.back() = 7;
  expect_invalid(soup, "face offsets");
  Soup decreasing = triangle();
  decreasing.corner_vertices = {0, 1, 2, 0, 1, 2};
  decreasing.face_begin = {0, 4, 3, 6};
  expect_invalid(decreasing, "face 1");
}

TEST(HostileSoup, all_faces_identical) {
  Soup soup = triangle();
  for (int i = 0; i < 999; ++i)
    soup.add_polygon({0, 1, 2});
  const DefectReport report = detect_defects(soup);
  EXPECT_EQ(report.duplicate_faces.size(), 999u);
  EXPECT_EQ(report.singular_edges.size(), 3u);
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.faces_out, 1000u);
}

TEST(HostileSoup, a_face_repeated_100000_times) {
  const double start = cpu_seconds();
  Soup soup;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)})
    soup.add_vertex(p);
  soup.add_polygon({0, 2, 1});  // a tetrahedron whose face 1 2 3 is repeated 10^5 times
  soup.add_polygon({0, 1, 3});
  soup.add_polygon({0, 3, 2});
  soup.add_polygon({1, 2, 3});
  for (int i = 0; i < 100000; ++i)
    soup.add_polygon({1, 2, 3});
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.faces_out, soup.num_faces());
  EXPECT_EQ(r.report.before.singular_edges.size(), 3u);
  EXPECT_EQ(r.report.before.duplicate_faces.size(), 100000u);
  // Linear work: well under a second. (Quadratic grouping or pairing takes ~10 s here.)
  EXPECT_LT(seconds_since(start), time_limit(3.0));
}

TEST(HostileSoup, one_edge_shared_by_10000_faces) {
  const double start = cpu_seconds();
  Soup soup;
  soup.add_vertex({0, 0, 0});
  soup.add_vertex({0, 0, 1});
  for (int i = 0; i < 10000; ++i) {
    const double angle = 2 * M_PI * i / 10000;
    const Index v = soup.add_vertex({std::cos(angle), std::sin(angle), 0.5});
    if (i % 2)
      soup.add_polygon({0, 1, v});
    else
      soup.add_polygon({1, 0, v});
  }
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  ASSERT_EQ(r.report.before.singular_edges.size(), 1u);
  EXPECT_EQ(r.report.before.singular_edges[0].contenders, 10000u);
  EXPECT_EQ(r.report.faces_out, 10000u);
  EXPECT_LT(seconds_since(start), time_limit(10.0));
}

TEST(HostileSoup, one_vertex_shared_by_100000_separate_fans) {
  const double start = cpu_seconds();
  Soup soup;
  soup.add_vertex({0, 0, 0});
  for (int i = 0; i < 100000; ++i) {
    const double angle = 2 * M_PI * i / 100000;
    soup.add_vertex({std::cos(angle), std::sin(angle), 1});
    soup.add_vertex({std::cos(angle), std::sin(angle), 2});
  }
  // Faces in decreasing vertex order: the shared vertex meets its 2 * 10^5 sides backwards.
  for (Index i = 100000; i-- > 0;)
    soup.add_polygon({0, 1 + 2 * i, 2 + 2 * i});
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.before.pinch_vertices, std::vector<Index>{0});
  EXPECT_EQ(r.report.vertices_split, 99999u);
  EXPECT_EQ(r.report.components_after, 100000u);
  // Linear work: well under a second. (Quadratic grouping takes ~10 s per pass here.)
  EXPECT_LT(seconds_since(start), time_limit(3.0));
}

TEST(HostileSoup, every_position_coincident) {
  Soup soup;
  for (int i = 0; i < 8; ++i)
    soup.add_vertex({1, 1, 1});
  // two cubes' worth of combinatorics on one point: no usable geometry anywhere
  soup.add_polygon({0, 2, 3, 1});
  soup.add_polygon({4, 5, 7, 6});
  soup.add_polygon({0, 1, 5, 4});
  soup.add_polygon({2, 6, 7, 3});
  soup.add_polygon({0, 4, 6, 2});
  soup.add_polygon({1, 3, 7, 5});
  soup.add_polygon({0, 1, 5, 4});
  soup.add_polygon({0, 1, 2});
  const DefectReport report = detect_defects(soup);
  EXPECT_EQ(report.zero_area_faces.size(), soup.num_faces());
  for (PairingPolicy pairing : {PairingPolicy::geometric, PairingPolicy::combinatorial}) {
    RepairOptions options;
    options.pairing = pairing;
    expect_repair_invariants(soup, repair(soup, options));
  }
}

TEST(HostileSoup, polygon_with_100000_corners) {
  Soup soup;
  std::vector<Index> ring;
  for (int i = 0; i < 100000; ++i) {
    const double angle = 2 * M_PI * i / 100000;
    ring.push_back(soup.add_vertex({std::cos(angle), std::sin(angle), 0}));
  }
  soup.add_polygon(ring);
  std::reverse(ring.begin(), ring.end());
  soup.add_polygon(ring);
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.after.num_components, 1u);
  EXPECT_TRUE(r.report.after.boundary_edges.empty());
}

TEST(HostileSoup, polygon_revisiting_one_vertex_many_times) {
  Soup soup;
  const Index center = soup.add_vertex({0, 0, 0});
  std::vector<Index> star;
  for (int i = 0; i < 50; ++i) {
    const double angle = 2 * M_PI * i / 50;
    const Index a = soup.add_vertex({std::cos(angle), std::sin(angle), 0});
    const Index b = soup.add_vertex({std::cos(angle + 0.05), std::sin(angle + 0.05), 0});
    star.insert(star.end(), {center, a, b});
  }
  soup.add_polygon(star);
  soup.add_polygon({0, 0, 0, 0});
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.faces_set_aside, 1u);
  EXPECT_EQ(r.report.faces_split, 1u);
  EXPECT_EQ(r.report.faces_out, 50u);
}

TEST(HostileSoup, extreme_and_denormal_coordinates) {
  for (double scale : {1e300, 1e-310, 1e154}) {
    SCOPED_TRACE(scale);
    Soup soup;
    for (int i = 0; i < 14; ++i)
      soup.add_vertex({double(i % 3) * scale, double((i / 3) % 3) * scale, double(i / 9) * scale});
    // a book of three on edge 0-1 plus a bowtie at vertex 4
    soup.add_polygon({0, 1, 3});
    soup.add_polygon({1, 0, 4});
    soup.add_polygon({0, 1, 9});
    soup.add_polygon({4, 5, 8});
    soup.add_polygon({4, 10, 11});
    soup.add_polygon({12, 13, 4});
    expect_repair_invariants(soup, repair(soup));
  }
}

TEST(HostileSoup, soup_with_no_faces_and_no_vertices) {
  const Soup empty;
  EXPECT_NO_THROW(validate_soup(empty));
  const RepairResult r = repair(empty);
  EXPECT_EQ(r.mesh.soup.num_faces(), 0u);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 0u);
  Soup points;
  points.add_vertex({0, 0, 0});
  points.add_vertex({0, 0, 0});
  const RepairResult p = repair(points);
  EXPECT_EQ(p.mesh.soup.num_vertices(), 2u);
  EXPECT_EQ(p.report.after.isolated_vertices.size(), 2u);
}
