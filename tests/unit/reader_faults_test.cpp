// SPDX-License-Identifier: GPL-3.0-or-later
// What a second first-time user's files showed the readers passing over without a word: OFF
// words that are no number after a vertex or a face, colour values clamped into range (OFF,
// PLY), a PLY coordinate that is nan or a PLY index out of range named without its line, an
// ASCII STL cut off inside a facet named as a facet with too few vertices, and an OFF or 3MF file
// under an OBJ name called "no polygons" without saying what it looks like. Each is now a counted
// fault (NotKept::fault) or an error that names the line.

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

class ReaderFaults : public test_support::ScratchFolderTest {
 protected:
  ReaderFaults() : ScratchFolderTest("faults") {}
  //! The error message reading `bytes` as `name` gives, or "read without error".
  std::string error_of(const std::string& name, const std::string& bytes) const {
    try {
      read_soup(write(name, bytes));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "read without error";
  }
  //! The NotKept entry whose text holds `part`, or nullptr.
  static const NotKept* entry(const MeshAttributes& attributes, const std::string& part) {
    for (const NotKept& n : attributes.not_kept) {
      if (n.what.find(part) != std::string::npos)
        return &n;
    }
    return nullptr;
  }
};

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << part << "' not in: " << text;
}

const char* kOffVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST_F(ReaderFaults, off_words_that_are_no_number_are_counted_per_line) {
  for (const char* header : {"OFF\n", "COFF\n"}) {
    MeshAttributes attributes;
    ReadInfo info;
    const Soup soup =
        read_soup(write("words.off", std::string(header) + "4 3 0\n0 0 0 abc\n1 0 0\n0 1 0 x y\n"
                                                           "0 0 1\n3 0 1 2 hello\n3 0 1 3 # fine\n"
                                                           "3 0 2 3 7 world\n"),
                  &info, &attributes);
    EXPECT_EQ(soup.num_faces(), 3u);
    EXPECT_EQ(info.faces_kept, 3u);
    const NotKept* vertices = entry(attributes, "after a vertex's numbers that are no number");
    const NotKept* faces = entry(attributes, "after a face's numbers that are no number");
    ASSERT_NE(vertices, nullptr) << header;
    ASSERT_NE(faces, nullptr) << header;
    EXPECT_EQ(vertices->count, 2u);  // "abc", "x y": one line each
    EXPECT_EQ(faces->count, 2u);     // a comment is no fault
    EXPECT_TRUE(vertices->fault);
    EXPECT_TRUE(faces->fault);
    EXPECT_FALSE(faces->clamped);
  }
  // A clean file has no such entry.
  MeshAttributes clean;
  read_soup(write("clean.off", std::string("OFF\n4 2 0\n") + kOffVertices + "3 0 1 2\n3 0 1 3\n"),
            nullptr, &clean);
  EXPECT_TRUE(clean.not_kept.empty());
}

TEST_F(ReaderFaults, off_colors_out_of_range_are_clamped_and_counted) {
  MeshAttributes attributes;
  read_soup(write("colours.off",
                  "COFF\n4 3 0\n0 0 0 300 0 0\n1 0 0 -5 0 0\n0 1 0 nan 0 0\n"
                  "0 0 1 0 128 0\n3 0 1 2 1.5 0.2 0.2\n3 0 1 3 255 0 0\n"
                  "3 0 2 3 0.5 0.5 0.5\n"),
            nullptr, &attributes);
  ASSERT_EQ(attributes.vertex_colors.size(), 4u);
  EXPECT_EQ(attributes.vertex_colors[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(attributes.vertex_colors[1], (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(attributes.vertex_colors[2], (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(attributes.vertex_colors[3], (Rgba{0, 128, 0, 255}));
  EXPECT_EQ(attributes.face_colors[0], (Rgba{255, 51, 51, 255}));
  const NotKept* vertices = entry(attributes, "OFF vertex colour values outside");
  const NotKept* faces = entry(attributes, "OFF face colour values outside");
  ASSERT_NE(vertices, nullptr);
  ASSERT_NE(faces, nullptr);
  EXPECT_EQ(vertices->count, 3u);
  EXPECT_EQ(faces->count, 1u);
  EXPECT_TRUE(vertices->fault && vertices->clamped);
  // What a writer says of them: written, as clamped.
  const std::vector<std::string> notes = describe_unwritten("out.ply", attributes);
  bool said = false;
  for (const std::string& note : notes)
    said = said || contains(note, "clamped to the range, on 3 vertices: written clamped");
  EXPECT_TRUE(said);
}

TEST_F(ReaderFaults, ply_colors_out_of_range_are_clamped_and_counted) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty int red\nproperty int green\nproperty float blue\n"
      "element face 2\nproperty list uchar int vertex_indices\nproperty float red\n"
      "property float green\nproperty float blue\nend_header\n";
  MeshAttributes attributes;
  read_soup(write("colours.ply", header + "0 0 0 300 0 0.5\n1 0 0 0 0 2\n0 1 0 0 0 1\n"
                                          "3 0 1 2 1 1 1\n3 0 2 1 -0.5 0 0\n"),
            nullptr, &attributes);
  EXPECT_EQ(attributes.vertex_colors[0].r, 255);
  EXPECT_EQ(attributes.vertex_colors[1].b, 255);
  const NotKept* vertices = entry(attributes, "PLY vertex colour values outside");
  const NotKept* faces = entry(attributes, "PLY face colour values outside");
  ASSERT_NE(vertices, nullptr);
  ASSERT_NE(faces, nullptr);
  EXPECT_EQ(vertices->count, 2u);
  EXPECT_EQ(faces->count, 1u);
}

TEST_F(ReaderFaults, ply_non_finite_coordinates_and_bad_indices_name_their_line) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_TRUE(contains(error_of("nan.ply", header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
                       "nan.ply: PLY vertex 2 of 3 (index 1) (line 11) has a non-finite "
                       "coordinate (nan or inf)"));
  EXPECT_TRUE(contains(error_of("inf.ply", header + "0 0 0\n1 0 0\n\n0 -inf 0\n3 0 1 2\n3 0 2 1\n"),
                       "PLY vertex 3 of 3 (index 2) (line 13) has a non-finite coordinate"));
  // A blank line between items is skipped in the count of lines, as the reader skips it.
  EXPECT_TRUE(contains(error_of("neg.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n3 0 -5 1\n"),
                       "neg.ply: PLY face 2 (line 15) refers to vertex index -5, but the file has "
                       "3 vertices (indices count from 0)"));
  EXPECT_TRUE(contains(error_of("big.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 9 1\n"),
                       "PLY face 2 (line 14) refers to vertex index 9, but the file has 3"));
  // Binary: no line to name, the item still.
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nelement face 0\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float xyz[3] = {0, std::numeric_limits<float>::infinity(), 0};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  EXPECT_TRUE(contains(error_of("inf_binary.ply", binary),
                       "PLY vertex 1 of 1 (index 0) has a non-finite coordinate"));
}

TEST_F(ReaderFaults, ascii_stl_cut_off_inside_a_facet_says_so) {
  const std::string first =
      "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n";
  EXPECT_TRUE(contains(error_of("in_a_keyword.stl", first + "vert"),
                       "ASCII STL line 12: the file ends inside facet 2 after 1 of its 3 "
                       "vertices, at 'vert' (truncated)"));
  EXPECT_TRUE(contains(error_of("after_two.stl", first + "vertex 1 0 0\n\n"),
                       "the file ends inside facet 2 after 2 of its 3 vertices (truncated)"));
  EXPECT_TRUE(contains(error_of("in_a_vertex.stl", first + "vertex 1 0"),
                       "line 12: facet 2, corner 2 is not 'vertex x y z' with three finite "
                       "numbers (32-bit floats); the file ends there (truncated?)"));
  EXPECT_TRUE(contains(error_of("in_endloop.stl", first + "vertex 1 0 0\nvertex 0 1 0\nendlo"),
                       "'endlo' where facet 2 (line 9) needs 'endloop' (a truncated file?)"));
  // Not cut off: a facet with 2 vertices and more after it is still named as such.
  EXPECT_TRUE(contains(error_of("two.stl", first + "vertex 1 0 0\nendloop\nendfacet\nendsolid\n"),
                       "facet 2 has 2 vertices; an STL facet is a triangle (3)"));
}

TEST_F(ReaderFaults, off_and_3mf_under_an_obj_name_are_named_as_what_they_look_like) {
  const std::string body = std::string("4 2 0\n") + kOffVertices + "3 0 1 2\n3 0 1 3\n";
  EXPECT_TRUE(contains(error_of("counts.obj", body),
                       "no polygons in the file (0 vertices); it begins with the counts '4 2 0': "
                       "an OFF file under another name?"));
  EXPECT_TRUE(contains(error_of("comment.obj", "# written by x\n\n  COFF  \n" + body),
                       "it begins with 'COFF': an OFF file under another name?"));
  EXPECT_TRUE(contains(error_of("bom.obj", "\xEF\xBB\xBFOFF\n" + body),
                       "it begins with 'OFF': an OFF file under another name?"));
  EXPECT_TRUE(contains(error_of("stoff.obj", "STCNOFF\n" + body),
                       "it begins with 'STCNOFF': an OFF file under another name?"));
  EXPECT_TRUE(contains(error_of("zip.obj", std::string("PK\3\4\24\0\0\0\10\0", 10)),
                       "it begins with 'PK': a zip archive (a 3MF file under another name?)"));
  // Where the reader refuses the file outright, the same hint ends its error.
  EXPECT_TRUE(
      contains(error_of("zip.ply", std::string("PK\3\4\24\0\0\0\10\0", 10)),
               "not a PLY file: it starts with 'PK\?\?\?\?\?\?\?\?', not 'ply'; it begins with "
               "'PK': a zip archive (a 3MF file under another name?)"));
  EXPECT_TRUE(
      contains(error_of("ply.off", "ply\nformat ascii 1.0\nend_header\n"),
               "not an OFF file: it starts with 'ply', not a header such as OFF, COFF, "
               "NOFF, STOFF or nOFF; it begins with 'ply': a PLY file under another name?"));
  EXPECT_TRUE(contains(error_of("off.stl", "OFF\n" + body),
                       "neither ASCII STL (no 'solid') nor binary STL"));
  EXPECT_TRUE(contains(error_of("off.stl", "OFF\n" + body),
                       "; it begins with 'OFF': an OFF file under another name?"));
  // Text that is neither: no guess.
  EXPECT_TRUE(contains(error_of("words.obj", "hello world\n1 2 3 4\n"),
                       "no polygons in the file (0 vertices)"));
  EXPECT_FALSE(contains(error_of("words.obj", "hello world\n1 2 3 4\n"), "another name"));
  EXPECT_FALSE(contains(error_of("four.obj", "1 2 3 4\n"), "another name"));
  // An OFF number that no double holds says so.
  EXPECT_TRUE(contains(error_of("huge.off", "OFF\n1 0 0\n1e400 0 0\n"),
                       "found '1e400', which is no number a double can hold"));
}

const char* kAsciiTriangle =
    "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
    "endloop\nendfacet\nendsolid x\n";

TEST_F(ReaderFaults, stl_padding_a_streamed_count_and_a_fourth_number) {
  // NUL bytes or a ^Z after an ASCII STL: padding, counted, not "binary data".
  for (const std::string& padding : {std::string(4, '\0'), std::string("\x1a")}) {
    ReadInfo info;
    EXPECT_EQ(read_soup(write("padded.stl", kAsciiTriangle + padding), &info).num_faces(), 1u);
    EXPECT_EQ(info.trailing_bytes, padding.size());
    EXPECT_TRUE(contains(describe_reading(info), "after the end of the mesh not read"));
  }
  // A binary STL whose header counts 0 triangles (a writer that streams its facets): read whole,
  // and named.
  std::string binary(80, ' ');
  binary += std::string(4, '\0');
  const float corners[2][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 0, 1}};
  for (const float* facet : corners) {
    binary += std::string(12, '\0');  // the normal
    binary.append(reinterpret_cast<const char*>(facet), 36);
    binary += std::string(2, '\0');  // the attribute word
  }
  MeshAttributes attributes;
  ReadInfo info;
  EXPECT_EQ(read_soup(write("streamed.stl", binary), &info, &attributes).num_faces(), 2u);
  EXPECT_EQ(info.declared_faces, 2u);
  ASSERT_EQ(attributes.not_kept.size(), 1u);
  EXPECT_TRUE(contains(attributes.not_kept[0].what,
                       "binary STL header that counts 0 triangles (a streaming writer's) before 2 "
                       "whole facets, all read"));
  EXPECT_TRUE(attributes.not_kept[0].fault);
  // A header that counts 0 before a stray byte is still an error.
  EXPECT_TRUE(contains(error_of("stray.stl", binary + "x"), "a binary STL whose header counts 0"));
  // A count of 1 before 2 whole facets: both read, named; a count of 3 with 2 whole facets and a
  // part of the third: a truncated file, said so.
  std::string one = binary;
  one[80] = 1;
  attributes = MeshAttributes();
  EXPECT_EQ(read_soup(write("one.stl", one), nullptr, &attributes).num_faces(), 2u);
  ASSERT_EQ(attributes.not_kept.size(), 1u);
  EXPECT_TRUE(contains(attributes.not_kept[0].what,
                       "binary STL header that counts 1 triangles before 2 whole facets, all "
                       "read"));
  // What such facets carry is named as for a whole binary STL (an attribute word here).
  std::string colored = one;
  colored[84 + 48] = 5;
  attributes = MeshAttributes();
  read_soup(write("coloured.stl", colored), nullptr, &attributes);
  ASSERT_EQ(attributes.not_kept.size(), 2u);
  EXPECT_TRUE(contains(attributes.not_kept[0].what, "binary STL facet attribute words"));
  std::string three = binary + std::string(20, '\0');
  three[80] = 3;
  EXPECT_TRUE(contains(error_of("three.stl", three),
                       "a binary STL whose header counts 3 triangles has 234 bytes, this file has "
                       "204 (2 whole facets: a truncated file?)"));
  // Four numbers after 'vertex'.
  std::string four = kAsciiTriangle;
  four.replace(four.find("vertex 1 0 0"), 12, "vertex 1 0 0 7");
  EXPECT_TRUE(contains(error_of("four.stl", four),
                       "ASCII STL line 5: facet 1, corner 2: more than 3 numbers after 'vertex'"));
  // Cut anywhere inside the solid: every error says the file may be cut short.
  const std::string whole = kAsciiTriangle;
  for (std::size_t size = 9; size + 12 < whole.size(); ++size) {
    const std::string error = error_of("cut.stl", whole.substr(0, size));
    EXPECT_TRUE(contains(error, "truncated")) << size;
  }
}

TEST_F(ReaderFaults, ply_with_a_byte_order_mark_or_cr_line_ends) {
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_soup(write("bom.ply", "\xEF\xBB\xBF" + ply)).num_faces(), 1u);
  std::string cr = ply;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  EXPECT_TRUE(contains(error_of("cr.ply", cr),
                       "cr.ply: its header lines end in CR alone (classic Mac OS text)"));
}

TEST_F(ReaderFaults, off_keyword_glued_to_its_counts_and_damaged_binary_off) {
  // ModelNet writes "OFF8 6 12": the keyword and the counts without a blank.
  ReadInfo info;
  EXPECT_EQ(
      read_soup(write("glued.off", std::string("OFF4 2 0\n") + kOffVertices + "3 0 1 2\n3 0 1 3\n"),
                &info)
          .num_faces(),
      2u);
  EXPECT_EQ(info.declared_vertices, 4u);
  // Geomview's big-endian binary OFF: a trailing newline is padding; a cut file names its own
  // counts, not little-endian garbage.
  const auto big = [](std::uint32_t w) {
    const std::uint32_t b = __builtin_bswap32(w);
    return std::string(reinterpret_cast<const char*>(&b), 4);
  };
  const auto big_float = [&big](float x) {
    std::uint32_t w = 0;
    std::memcpy(&w, &x, 4);
    return big(w);
  };
  std::string body = big(4) + big(2) + big(0);
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f})
    body += big_float(x);
  for (std::uint32_t c : {0u, 1u, 2u})
    body += (c == 0 ? big(3) : "") + big(c);
  body += big(0);
  for (std::uint32_t c : {0u, 1u, 3u})
    body += (c == 0 ? big(3) : "") + big(c);
  body += big(0);
  ReadInfo padded;
  EXPECT_EQ(read_soup(write("newline.off", "OFF BINARY\n" + body + "\n"), &padded).num_faces(), 2u);
  EXPECT_EQ(padded.trailing_bytes, 1u);
  const std::string cut = error_of("cut.off", "OFF BINARY\n" + body.substr(0, body.size() - 6));
  EXPECT_TRUE(contains(cut, "binary OFF face 2")) << cut;
  // Cut inside the last face's colour count: named, never read past the end (a fuzz finding).
  const std::string in_count =
      error_of("in_count.off", "OFF BINARY\n" + body.substr(0, body.size() - 2));
  EXPECT_TRUE(contains(in_count, "binary OFF ends in face 2, before its colour count")) << in_count;
  std::string many = body;
  many.replace(many.size() - 4, 4, big(1000));
  EXPECT_TRUE(contains(error_of("many.off", "OFF BINARY\n" + many + std::string(8, '\0')),
                       "binary OFF face 2 claims 1000 colour values, more than the rest of the "
                       "file holds"));
}

TEST_F(ReaderFaults, obj_corner_and_keyword_messages) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_TRUE(contains(error_of("dash.obj", triangle + "f 3 -\n"),
                       "line 4: face corner '-' has no vertex index"));
  EXPECT_TRUE(contains(error_of("upper.obj", triangle + "F 1 2 3\n"),
                       "no polygons in the file (3 vertices); 1 line with an unknown keyword "
                       "skipped (a misspelt or upper-case 'f'?)"));
}

}  // namespace
}  // namespace meshbridge
