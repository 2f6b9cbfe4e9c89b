// SPDX-License-Identifier: GPL-3.0-or-later
// What a first-time user's messy files showed the readers losing without a word: an OBJ comment
// ending in a backslash (a Windows path) that swallowed the next record, misspelt OBJ keywords,
// OFF and ASCII PLY files whose counts are lower than what they hold, and ASCII STL facets with
// four corners or a misspelt keyword. Each is now kept, counted or a clear error.

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

class ReaderStrictness : public test_support::ScratchFolderTest {
 protected:
  ReaderStrictness() : ScratchFolderTest("strict") {}
  //! The ReadError message reading `bytes` as `name` gives, or "read without error".
  std::string error_of(const std::string& name, const std::string& bytes) const {
    try {
      read_soup(write(name, bytes));
    } catch (const ReadError& e) {
      return e.what();
    }
    return "read without error";
  }
};

//! Success if `text` holds `part`; the message shows `text` otherwise.
::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << part << "' not in: " << text;
}

const char* kTetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
const char* kOffTetrahedron = "4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST_F(ReaderStrictness, obj_comment_ending_in_a_backslash_does_not_swallow_the_next_record) {
  const std::string faces = "f 1 3 2\nf 1 2 4\n";
  for (const std::string& comment :
       {std::string("# texture dir D:\\tex\\\n"), std::string("#D:\\tex\\\r\n"),
        std::string("f 2 3 4 # \\\n")}) {
    SCOPED_TRACE(comment);
    std::string text = std::string(kTetrahedron) + faces + comment + "f 1 4 3\n";
    if (comment[0] == '#')
      text += "f 2 3 4\n";
    ReadInfo info;
    const Soup soup = read_soup(write("comment.obj", text), &info);
    EXPECT_EQ(soup.num_faces(), 4u);
    EXPECT_EQ(info.declared_faces, 4u);
  }
  // A comment before the first vertex, ending in a backslash: the vertex is kept.
  const Soup first = read_soup(
      write("first.obj", "# from C:\\models\\\n" + std::string(kTetrahedron) + "f 1 2 3\n"));
  EXPECT_EQ(first.num_vertices(), 4u);
  // '#' inside a word is no comment: the group line continues onto the next one (which would
  // otherwise be a line with the unknown keyword "rest").
  ReadInfo info;
  MeshAttributes attributes;
  read_soup(write("group.obj", std::string(kTetrahedron) + "g part#2 \\\n rest\nf 1 2 3\n"), &info,
            &attributes);
  ASSERT_EQ(attributes.face_groups.size(), 1u);
  EXPECT_NE(attributes.face_groups[0].name.find("rest"), std::string::npos);
  EXPECT_EQ(info.unknown_records, 0u);
}

TEST_F(ReaderStrictness, obj_lines_with_unknown_keywords_are_counted) {
  ReadInfo info;
  const Soup soup = read_soup(
      write("unknown.obj", std::string(kTetrahedron) + "vt 0 0\nvn 0 0 1\ns off\nmtllib a.mtl\n"
                                                       "cstype bezier\nf 1 2 3\nfo 1 3 4\n"
                                                       "F 1 2 4\nvx 1 2 3\n"),
      &info);
  EXPECT_EQ(soup.num_faces(), 2u);  // "fo" is the old face keyword
  EXPECT_EQ(info.unknown_records, 2u);
  EXPECT_TRUE(info.changed_anything());
  EXPECT_NE(describe_reading(info).find("2 lines with an unknown keyword skipped"),
            std::string::npos);
}

TEST_F(ReaderStrictness, off_and_ascii_ply_holding_more_faces_than_declared_are_errors) {
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  // Four faces given, three declared.
  EXPECT_NE(error_of("lie.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces)
                .find("OFF declares 3 faces, but more follows them (line 10): '3'"),
            std::string::npos);
  // Comments and blank lines after the last face are fine.
  EXPECT_EQ(
      read_soup(write("tail.off", "OFF\n" + std::string(kOffTetrahedron) + faces + "\n# end\n\n"))
          .num_faces(),
      4u);
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  EXPECT_NE(error_of("fewer.ply", header + faces)
                .find("ascii PLY: line 17: values after the last declared item (face 3)"),
            std::string::npos);
  EXPECT_EQ(read_soup(write("exact.ply", header + "3 0 2 1\n3 0 1 3\n3 1 2 3\n\n")).num_faces(),
            3u);
}

TEST_F(ReaderStrictness, ascii_stl_is_read_as_its_grammar) {
  const auto facet = [](const std::string& loop, const std::string& corners) {
    return "facet normal 0 0 1\n " + loop + "\n" + corners + " endloop\nendfacet\n";
  };
  const std::string triangle = "vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n";
  // "outerloop" and two solids read.
  ReadInfo info;
  EXPECT_EQ(read_soup(write("variants.stl", "solid a\n" + facet("outerloop", triangle) +
                                                "endsolid a\nsolid b\n" +
                                                facet("outer loop", triangle) + "endsolid b\n"),
                      &info)
                .num_faces(),
            2u);
  EXPECT_EQ(info.declared_faces, 2u);
  // A facet with four corners is not cut to a triangle.
  EXPECT_NE(error_of("quad.stl", "solid q\n" + facet("outer loop", triangle + "vertex 0 1 0\n"))
                .find("ASCII STL line 2: facet 1 has 4 vertices; an STL facet is a triangle (3)"),
            std::string::npos);
  // A misspelt keyword is named, not skipped with its facet.
  EXPECT_NE(error_of("typo.stl", "solid t\n" + facet("outer lop", triangle))
                .find("line 3: 'lop' after 'outer' (expected 'outer loop')"),
            std::string::npos);
  EXPECT_NE(error_of("junk.stl", "solid t\n" + facet("outer loop", triangle) + "endsolid t\nxyz\n")
                .find("line 10: 'xyz' where 'solid' or the end of the file was expected"),
            std::string::npos);
  EXPECT_NE(error_of("junk2.stl", "solid t\n" + facet("outer loop", triangle) + "xyz\n")
                .find("line 9: 'xyz' where a facet, 'solid' or 'endsolid' was expected"),
            std::string::npos);
  EXPECT_NE(error_of("cut.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n")
                .find("the file ends inside facet 1 after 1 of its 3 vertices (truncated)"),
            std::string::npos);
  // A file cut short between facets, or a facet without its endloop or endfacet, is not read as
  // a whole one.
  const std::string two =
      "solid t\n" + facet("outer loop", triangle) + facet("outer loop", triangle);
  EXPECT_TRUE(contains(error_of("no_endsolid.stl", two),
                       "no_endsolid.stl: ASCII STL line 16: the file ends inside the solid of "
                       "line 1, without 'endsolid' (a truncated file?)"));
  EXPECT_TRUE(contains(error_of("cut_after_endloop.stl", two.substr(0, two.rfind("endfacet"))),
                       "line 15: the end of the file where facet 2 (line 9) needs 'endfacet' (a "
                       "truncated file?)"));
  std::string no_endloop = two + "endsolid t\n";
  no_endloop.erase(no_endloop.find(" endloop\n"), 9);
  EXPECT_TRUE(contains(error_of("no_endloop.stl", no_endloop),
                       "line 7: 'endfacet' where facet 1 (line 2) needs 'endloop'"));
  EXPECT_TRUE(contains(error_of("two_solids.stl", "solid a\n" + facet("outer loop", triangle) +
                                                      "solid b\nendsolid b\n"),
                       "line 9: 'solid' inside the solid of line 1 (its 'endsolid' is missing)"));
  EXPECT_TRUE(contains(error_of("end_only.stl", "solid a\nendsolid a\nendsolid a\n"),
                       "line 3: 'endsolid' without a 'solid' before it"));
}

TEST_F(ReaderStrictness, binary_stl_with_a_solid_header_and_a_wrong_size_is_named_binary) {
  std::string bytes(84 + 50, '\0');
  bytes.replace(0, 10, "solid part");
  bytes[80] = 1;  // one triangle
  for (const std::string& file : {bytes.substr(0, 120), bytes + "xy"}) {
    EXPECT_NE(error_of("solid_binary.stl", file)
                  .find("binary data after a header that begins with 'solid', but not a whole "
                        "binary STL: a binary STL whose header counts 1 triangles has 134 bytes"),
              std::string::npos);
  }
}

// A binary OFF tetrahedron: 32-bit words in the given byte order, each face followed by a colour
// count of 0 (Geomview's specification) or by nothing (OpenMesh's layout).
std::string binary_off(bool big_endian, bool color_counts) {
  std::string bytes = "OFF BINARY\n";
  const auto put = [&](std::uint32_t w) {
    for (int i = 0; i < 4; ++i)
      bytes += static_cast<char>(big_endian ? w >> (24 - 8 * i) : w >> (8 * i));
  };
  const auto put_float = [&](float x) {
    std::uint32_t w = 0;
    std::memcpy(&w, &x, 4);
    put(w);
  };
  for (std::uint32_t n : {4u, 4u, 0u})
    put(n);
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f})
    put_float(x);
  for (const auto& face : {std::vector<std::uint32_t>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}) {
    put(3);
    for (std::uint32_t v : face)
      put(v);
    if (color_counts)
      put(0);
  }
  return bytes;
}

TEST_F(ReaderStrictness, binary_off_in_openmesh_and_geomview_layouts) {
  for (const bool big_endian : {false, true}) {
    for (const bool color_counts : {false, true}) {
      SCOPED_TRACE(std::string(big_endian ? "big" : "little") + " endian, " +
                   (color_counts ? "with" : "without") + " colour counts");
      ReadInfo info;
      const Soup soup = read_soup(write("b.off", binary_off(big_endian, color_counts)), &info);
      ASSERT_EQ(soup.num_faces(), 4u);
      EXPECT_EQ(info.faces_kept, 4u);
      EXPECT_EQ(soup.positions[3], Point(0, 0, 1));
      EXPECT_EQ(soup.polygon(3)[2], 2u);
    }
  }
  EXPECT_NE(error_of("tail.off", binary_off(false, false) + "junk")
                .find("binary OFF: 4 bytes follow its last face"),
            std::string::npos);
}

TEST_F(ReaderStrictness, a_utf8_byte_order_mark_is_skipped_in_text_formats) {
  const std::string bom = "\xEF\xBB\xBF";
  EXPECT_EQ(read_soup(write("bom.off", bom + "OFF\n" + kOffTetrahedron +
                                           "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"))
                .num_faces(),
            4u);
  EXPECT_EQ(read_soup(write("bom.obj", bom + kTetrahedron + "f 1 2 3\n")).num_faces(), 1u);
  EXPECT_EQ(
      read_soup(write("bom.stl", bom + "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                       "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n"))
          .num_faces(),
      1u);
}

// OFF colours written as integers are 0..255, as floats 0..1. "1 1 1" is either: in a file that
// writes other colours as floats it is white, in one that writes only integers it stays 1/255.
// Whether a colour is integer is decided by its own values, not by the normal before it.
TEST_F(ReaderStrictness, off_color_scale_is_decided_per_file) {
  const auto colors = [&](const std::string& name, const std::string& text) {
    MeshAttributes attributes;
    read_soup(write(name, text), nullptr, &attributes);
    return attributes.vertex_colors;
  };
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  const auto mixed = colors("mixed.off",
                            "COFF\n4 4 0\n0 0 0 1.0 0 0\n1 0 0 1 1 1\n0 1 0 0 1 0\n"
                            "0 0 1 0.5 0.5 0.5\n" +
                                faces);
  ASSERT_EQ(mixed.size(), 4u);
  EXPECT_EQ(mixed[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(mixed[1], (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(mixed[2], (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(mixed[3], (Rgba{128, 128, 128, 255}));
  const auto integers = colors("integers.off",
                               "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 1 1 1\n0 1 0 0 255 0\n"
                               "0 0 1 9 9 9\n" +
                                   faces);
  EXPECT_EQ(integers[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(integers[1], (Rgba{1, 1, 1, 255}));
  const auto normals = colors("normals.off",
                              "CNOFF\n4 4 0\n0 0 0 0.6 0 0.8 255 0 0\n"
                              "1 0 0 0.6 0 0.8 0 255 0\n0 1 0 0 0 1 0 0 255\n"
                              "0 0 1 0 0 1 9 9 9\n" +
                                  faces);
  EXPECT_EQ(normals[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(normals[3], (Rgba{9, 9, 9, 255}));
}

TEST_F(ReaderStrictness, off_without_its_keyword_is_plain_off_and_one_line_is_named) {
  // Geomview: the keyword is "recommended but optional, as many existing files lack it".
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  for (const std::string& start :
       {std::string(""), std::string("# a comment\n\n"), std::string("  \r\n")}) {
    SCOPED_TRACE(start);
    ReadInfo info;
    const Soup soup = read_soup(write("bare.off", start + kOffTetrahedron + faces), &info);
    EXPECT_EQ(soup.num_vertices(), 4u);
    EXPECT_EQ(soup.num_faces(), 4u);
    EXPECT_EQ(info.faces_kept, 4u);
  }
  // A comment after the counts is fine; more numbers there are the file written on one line.
  EXPECT_EQ(error_of("counted.off", "OFF\n4 4 0 # V F E\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces),
            "read without error");
  EXPECT_NE(error_of("one_line.off",
                     "OFF 4 4 0 0 0 0 1 0 0 0 1 0 0 0 1 3 0 2 1 3 0 1 3 3 0 3 2 "
                     "3 1 2 3\n")
                .find("one_line.off: more follows the counts (line 1): '0' (OFF gives the "
                      "counts, each vertex and each face a line of its own"),
            std::string::npos);
  EXPECT_NE(error_of("junk.off", "hello 4 4 0\n").find("not an OFF file: it starts with 'hello'"),
            std::string::npos);
  // A vertex line missing: the first face is read as the last vertex, and the message says so.
  EXPECT_NE(error_of("short.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n")
                .find("OFF face 2 of 2 is missing: the file ends (a false count; or fewer "
                      "vertex lines than the 4 declared, so that a face was read as one)"),
            std::string::npos);
}

TEST_F(ReaderStrictness, cr_line_ends_alone_are_named) {
  for (const char* name : {"mac.obj", "mac.off"}) {
    const std::string text = std::string(name) == "mac.obj"
                                 ? "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r"
                                 : "OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r";
    EXPECT_NE(error_of(name, text).find("its lines end in CR alone (classic Mac OS text)"),
              std::string::npos)
        << error_of(name, text);
  }
  // CRLF is read as it is.
  EXPECT_EQ(error_of("dos.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"),
            "read without error");
}

TEST_F(ReaderStrictness, ascii_ply_errors_name_the_line_that_does_not_match_the_header) {
  // Line 1 is "ply"; the body starts on line 10.
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const auto error_with = [&](const std::string& name, const std::string& body) {
    return error_of(name, header + body);
  };
  EXPECT_TRUE(contains(error_with("extra.ply", "0 0 0\n1 0 0 5\n0 1 0\n3 0 1 2\n"),
                       "extra.ply: ascii PLY: line 11, vertex 2 of 3: 4 values where the "
                       "header's properties (x, y, z) take 3"));
  EXPECT_TRUE(contains(error_with("short.ply", "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
                       "line 11, vertex 2 of 3: the line ends before property 'z'"));
  EXPECT_TRUE(contains(error_with("list.ply", "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
                       "line 13, face 1 of 1: list 'vertex_indices' counts 3 entries, but the "
                       "line holds 2"));
  EXPECT_TRUE(contains(error_with("long.ply", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n"),
                       "line 13, face 1 of 1: 5 values where the header's properties "
                       "(vertex_indices) take 4"));
  EXPECT_TRUE(contains(error_with("word.ply", "0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n"),
                       "line 11, vertex 2 of 3: property 'z' is 'x', not a number"));
  EXPECT_TRUE(contains(error_with("frac.ply", "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"),
                       "line 13, face 1 of 1: entry 2 of list 'vertex_indices' is '1.5', not a "
                       "whole number (int)"));
  // Values hold their declared type, as the binary encoding would have to: a float within
  // float's range and finite, a uchar count 0 to 255.
  EXPECT_TRUE(
      contains(error_with("huge.ply", "0 0 0\n1 0 1e40\n0 1 0\n3 0 1 2\n"),
               "line 11, vertex 2 of 3: property 'z' is '1e40', outside the range of float"));
  // nan is a float (a binary file may hold it): read, and refused as a coordinate.
  EXPECT_THROW(read_soup(write("nan.ply", header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n")),
               InvalidSoupError);
  EXPECT_TRUE(contains(error_with("count.ply", "0 0 0\n1 0 0\n0 1 0\n256 0 1 2\n"),
                       "line 13, face 1 of 1: the count of list 'vertex_indices' is '256', "
                       "outside the range of uchar (0 to 255)"));
  // Blank lines and CRLF line ends count as lines.
  EXPECT_TRUE(contains(error_with("crlf.ply", "0 0 0\r\n\r\n1 0 0\r\n0 1\r\n3 0 1 2\r\n"),
                       "line 13, vertex 3 of 3: the line ends before property 'z'"));
  EXPECT_TRUE(contains(error_with("cut.ply", "0 0 0\n1 0 0\n0 1 0\n"),
                       "ascii PLY: the file ends after line 12, before face 1 of 1 (a truncated "
                       "file or a false count)"));
  EXPECT_TRUE(contains(error_with("after.ply", "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n7\n"),
                       "line 15: values after the last declared item (face 1)"));
  // Values wrapped over lines are still read (the reader takes words; only errors look at lines).
  EXPECT_EQ(read_soup(write("wrapped.ply", header + "0 0\n0\n1 0 0 0 1 0\n3 0 1 2\n")).num_faces(),
            1u);
}

TEST_F(ReaderStrictness, a_file_under_another_formats_name_is_named_as_what_it_looks_like) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_TRUE(contains(error_of("ply.obj", ply),
                       "no polygons in the file (0 vertices); it begins with 'ply': a PLY file "
                       "under another name?"));
  std::string stl(84, '\0');
  stl[80] = 1;
  stl += std::string(50, '\0');
  EXPECT_TRUE(contains(error_of("stl.obj", stl),
                       "its size is that of a binary STL of 1 triangle: an STL file under another "
                       "name?"));
  EXPECT_TRUE(contains(error_of("off.obj", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                       "it begins with 'OFF': an OFF file under another name?"));
  EXPECT_TRUE(contains(error_of("solid.obj", "solid x\nendsolid x\n"),
                       "it begins with 'solid': an ASCII STL file under another name?"));
  EXPECT_TRUE(contains(error_of("nul.obj", std::string("# \0\0\0\n", 6)),
                       "it holds binary data (a NUL byte at offset 2)"));
}

TEST_F(ReaderStrictness, an_off_non_finite_coordinate_and_a_false_binary_ply_count_are_named) {
  try {
    read_soup(write("nan.off", "OFF\n# a comment\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"));
    FAIL() << "no error";
  } catch (const InvalidSoupError& error) {
    EXPECT_TRUE(contains(error.what(),
                         "nan.off: OFF vertex 2 of 3 (line 5) has a non-finite "
                         "coordinate (nan or inf)"));
  }
  // A binary PLY whose vertex count is 1 too low reads its faces from the last vertex's bytes.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 0\n"
      "property list uchar int vertex_indices\nend_header\n";
  ply += std::string(4 * 12, '\0');
  EXPECT_TRUE(contains(error_of("lie.ply", ply),
                       "no polygons in the file (3 vertices); 12 bytes follow the last declared "
                       "element: a false count in the header?"));
}

TEST_F(ReaderStrictness, ascii_ply_values_outside_their_declared_type_are_named_by_line) {
  // A colour declared uchar that says 300, a coordinate declared int that says 0.5: no binary
  // file could hold them, and reading them anyhow (wrapped, clamped, rounded) would change them.
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  const std::string good = "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n";
  MeshAttributes attributes;
  EXPECT_EQ(read_soup(write("typed.ply", header + good), nullptr, &attributes).num_faces(), 1u);
  EXPECT_EQ(attributes.vertex_colors[1], (Rgba{0, 255, 0, 255}));
  EXPECT_TRUE(contains(error_of("red.ply", header + "0 0 0 255 0 0\n1 0 0 300 255 0\n0 1 0 0 0 "
                                                    "255\n3 0 1 2\n"),
                       "red.ply: ascii PLY: line 14, vertex 2 of 3: property 'red' is '300', "
                       "outside the range of uchar (0 to 255)"));
  EXPECT_TRUE(contains(error_of("int.ply", header + "0.5 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 "
                                                    "255\n3 0 1 2\n"),
                       "line 13, vertex 1 of 3: property 'x' is '0.5', not a whole number (int)"));
  EXPECT_TRUE(contains(error_of("uint.ply", header + "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 "
                                                     "255\n3 0 -1 2\n"),
                       "line 16, face 1 of 1: entry 2 of list 'vertex_indices' is '-1', outside "
                       "the range of uint (0 to 4294967295)"));
}

TEST_F(ReaderStrictness, obj_l_and_p_and_ply_edges_past_the_last_vertex_are_errors) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_TRUE(contains(error_of("p.obj", triangle + "l 1 3\np 9\n"),
                       "p.obj: line 6: point corner '9' refers to vertex 9, but the file has 3 "
                       "vertices"));
  EXPECT_TRUE(contains(error_of("l.obj", triangle + "l 2 100000\n"),
                       "line 5: line corner '100000' refers to vertex 100000"));
  // A forward reference to a vertex the file gives later is fine, as for faces.
  EXPECT_EQ(read_soup(write("forward.obj", "l 1 4\n" + triangle + "v 1 1 0\n")).num_faces(), 1u);
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_TRUE(contains(error_of("e.ply", ply + "0 3\n"),
                       "e.ply: PLY edge 1 of 1 (line 17): property 'vertex2' is vertex index 3, "
                       "but the file has 3 vertices"));
  EXPECT_TRUE(contains(error_of("n.ply", ply + "-1 2\n"), "property 'vertex1' is vertex index -1"));
  ReadInfo info;
  EXPECT_EQ(read_soup(write("ok.ply", ply + "0 2\n"), &info).num_faces(), 1u);
  EXPECT_EQ(info.dangling_edges, 1u);
}

}  // namespace
}  // namespace meshbridge
