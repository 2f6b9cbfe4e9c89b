// SPDX-License-Identifier: GPL-3.0-or-later
// Colours and OBJ side records as the file has them, no more and no less: an element without a
// colour stays without one where the format allows it (OBJ vertices, OFF faces), a PLY file's
// own channels are written back (no invented green or alpha), an OFF colour-map index is
// counted, `mtllib` lines are written back, and what an output format cannot hold is named by
// describe_unwritten().

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace meshbridge {
namespace {

class ColorFidelity : public test_support::ScratchFolderTest {
 protected:
  ColorFidelity() : ScratchFolderTest("colour") {}

  struct Reading {
    Soup soup;
    ReadInfo info;
    MeshAttributes attributes;
  };
  Reading read(const std::string& file) const {
    Reading r;
    r.soup = read_soup(file, &r.info, &r.attributes);
    return r;
  }
  //! Writes the soup of `r` unchanged (no repair) to `name` with its attributes; its path.
  std::string write_back(const Reading& r, const std::string& name) const {
    IndexedMesh mesh;
    mesh.soup = r.soup;
    write_mesh(path(name), mesh, &r.attributes);
    return path(name);
  }
  static std::vector<std::string> lines_of(const std::string& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }
};

const char* kTetrahedronFaces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

TEST_F(ColorFidelity, obj_vertices_without_a_color_stay_without_one) {
  const Reading r = read(write("partial.obj",
                               "mtllib a.mtl b.mtl\nv 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0.2 1 0.6\n"
                               "v 0 0 1\nvt 0 0\nvt 1 0\nvn 0 0 1\nusemtl red\n" +
                                   std::string(kTetrahedronFaces)));
  const auto& a = r.attributes;
  ASSERT_EQ(a.vertex_colors.size(), 4u);
  EXPECT_EQ(a.vertex_color_missing, (std::vector<bool>{false, true, false, true}));
  EXPECT_EQ(a.vertex_colors[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(a.vertex_colors[2], (Rgba{0, 51, 255, 153}));
  EXPECT_EQ(a.vertex_color_channels, kRgbaChannels);  // a 'v' line with r g b a
  EXPECT_EQ(a.material_libraries, (std::vector<std::string>{"mtllib a.mtl b.mtl"}));
  EXPECT_EQ(a.texture_coordinates, 2u);
  EXPECT_EQ(a.normals, 1u);

  const std::string out = write_back(r, "partial_out.obj");
  const std::vector<std::string> lines = lines_of(out);
  // comment, mtllib, v x 4, vt x 2 and vn (kept, though no face names them), usemtl, f x 4
  ASSERT_EQ(lines.size(), 1u + 1 + 4 + 3 + 1 + 4);
  EXPECT_EQ(lines[1], "mtllib a.mtl b.mtl");
  EXPECT_EQ(lines[2], "v 0 0 0 1 0 0 1");
  EXPECT_EQ(lines[3], "v 1 0 0");  // no colour invented
  EXPECT_EQ(lines[5], "v 0 0 1");
  EXPECT_EQ(lines[6], "vt 0 0");
  EXPECT_EQ(lines[8], "vn 0 0 1");
  EXPECT_EQ(lines[9], "usemtl red");
  const Reading back = read(out);
  EXPECT_EQ(back.attributes.vertex_colors, a.vertex_colors);
  EXPECT_EQ(back.attributes.vertex_color_missing, a.vertex_color_missing);
  EXPECT_EQ(back.attributes.material_libraries, a.material_libraries);

  // Without alpha anywhere, none is written; a file with colours on every vertex has no flags.
  const Reading opaque =
      read(write("opaque.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 0 0 1 1 1 1\n" +
                                   std::string(kTetrahedronFaces)));
  EXPECT_TRUE(opaque.attributes.vertex_color_missing.empty());
  EXPECT_EQ(opaque.attributes.vertex_color_channels, kRgbChannels);
  EXPECT_EQ(lines_of(write_back(opaque, "opaque_out.obj"))[1], "v 0 0 0 1 0 0");
}

TEST_F(ColorFidelity, off_faces_without_a_color_stay_without_one_and_keep_their_channels) {
  const char* text =
      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "3 0 2 1 200 0 0\n3 0 1 3\n3 0 3 2 0.5 0.5 0.5\n3 1 2 3\n";
  const Reading r = read(write("faces.off", text));
  const auto& a = r.attributes;
  ASSERT_EQ(a.face_colors.size(), 4u);
  EXPECT_EQ(a.face_color_missing, (std::vector<bool>{false, true, false, true}));
  EXPECT_EQ(a.face_color_channels, kRgbChannels);
  const std::vector<std::string> lines = lines_of(write_back(r, "faces_out.off"));
  ASSERT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines[6], "3 0 2 1 200 0 0");  // three values in, three out (no alpha added)
  EXPECT_EQ(lines[7], "3 0 1 3");          // no colour in, none out (was written white)
  EXPECT_EQ(lines[8], "3 0 3 2 128 128 128");
  EXPECT_EQ(lines[9], "3 1 2 3");
  // Alpha where the file gave it.
  const Reading alpha =
      read(write("alpha.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 10 20 30 40\n"));
  EXPECT_EQ(alpha.attributes.face_color_channels, kRgbaChannels);
  EXPECT_EQ(lines_of(write_back(alpha, "alpha_out.off"))[5], "3 0 1 2 10 20 30 40");
}

TEST_F(ColorFidelity, off_color_map_indices_are_counted_with_or_without_attributes) {
  const std::string file =
      write("colormap.off",
            "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 7\n0 0 1 0 0 255\n"
            "3 0 2 1 200 0 0\n3 0 1 3 4\n3 0 3 2\n3 1 2 3 9\n");
  const Reading r = read(file);
  EXPECT_EQ(r.info.color_map_indices, 3u);
  EXPECT_TRUE(r.info.changed_anything());
  EXPECT_NE(describe_reading(r.info).find("3 colours given as colour-map indices not kept"),
            std::string::npos)
      << describe_reading(r.info);
  EXPECT_EQ(r.attributes.vertex_color_missing, (std::vector<bool>{false, false, true, false}));
  EXPECT_EQ(r.attributes.face_color_missing, (std::vector<bool>{false, true, true, true}));
  ReadInfo bare;  // `check` reads without attributes: the same count
  read_soup(file, &bare);
  EXPECT_EQ(bare.color_map_indices, 3u);
  // COFF gives every vertex a colour: the one without gets white, and that is named.
  EXPECT_EQ(describe_unwritten(path("x.off"), r.attributes),
            (std::vector<std::string>{"1 vertex without a colour written white: OFF gives every "
                                      "vertex a colour or none"}));
}

TEST_F(ColorFidelity, ply_channels_are_written_back_as_the_file_had_them) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nelement face 1\n"
      "property list uchar int vertex_indices\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty uchar alpha\nend_header\n";
  const Reading r =
      read(write("red.ply", header + "0 0 0 10\n1 0 0 20\n0 1 0 30\n3 0 1 2 1 2 3 4\n"));
  EXPECT_EQ(r.attributes.vertex_color_channels, kRedChannel);
  EXPECT_EQ(r.attributes.face_color_channels, kRgbaChannels);
  const std::string out = write_back(r, "red_out.ply");
  std::ifstream in(out, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string written = bytes.str();
  const std::string vertex_part =
      written.substr(written.find("element vertex"),
                     written.find("element face") - written.find("element vertex"));
  EXPECT_NE(vertex_part.find("property uchar red\n"), std::string::npos) << vertex_part;
  EXPECT_EQ(vertex_part.find("green"), std::string::npos) << vertex_part;  // none invented
  EXPECT_EQ(vertex_part.find("alpha"), std::string::npos) << vertex_part;
  const Reading back = read(out);
  EXPECT_EQ(back.attributes.vertex_color_channels, kRedChannel);
  EXPECT_EQ(back.attributes.vertex_colors, r.attributes.vertex_colors);
  EXPECT_EQ(back.attributes.face_colors, r.attributes.face_colors);
}

TEST_F(ColorFidelity, ply_strip_triangles_have_no_color_and_off_writes_none_for_them) {
  const Reading r = read(
      write("strips.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "property uchar red\nproperty uchar green\nproperty uchar blue\nelement tristrips 1\n"
            "property list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
            "3 0 2 1 10 20 30\n4 0 1 3 2\n"));
  ASSERT_EQ(r.soup.num_faces(), 3u);
  EXPECT_EQ(r.attributes.face_color_missing, (std::vector<bool>{false, true, true}));
  const std::vector<std::string> lines = lines_of(write_back(r, "strips_out.off"));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[6], "3 0 2 1 10 20 30");
  EXPECT_EQ(lines[7].size(), 7u) << lines[7];  // "3 a b c", no colour
  EXPECT_EQ(describe_unwritten(path("x.ply"), r.attributes),
            (std::vector<std::string>{"2 faces without a colour written white: PLY gives every "
                                      "face a colour or none"}));
}

TEST_F(ColorFidelity, channels_a_file_lacked_are_named_where_the_format_needs_all_three) {
  MeshAttributes a;
  a.vertex_colors.resize(3);
  a.vertex_color_channels = kRedChannel;
  a.face_colors.resize(1);
  a.face_color_channels = kRedChannel | kBlueChannel | kAlphaChannel;
  const auto off = describe_unwritten("x.off", a);
  ASSERT_EQ(off.size(), 2u);
  EXPECT_EQ(off[0],
            "vertex colours written with green and blue 0: the file gave no green and blue, and "
            "OFF colours have red, green and blue");
  EXPECT_EQ(off[1],
            "face colours written with green 0: the file gave no green, and OFF colours "
            "have red, green and blue");
  const auto obj = describe_unwritten("x.obj", a);  // OBJ holds no face colours at all
  ASSERT_EQ(obj.size(), 2u);
  EXPECT_EQ(obj[0], "face colours not written: OBJ holds none");
  EXPECT_EQ(obj[1].substr(0, 44), "vertex colours written with green and blue 0");
  EXPECT_TRUE(describe_unwritten("x.ply", a).empty());  // PLY writes the file's own channels
  // Read from a PLY of red only.
  const Reading r = read(write("red.ply",
                               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nproperty uchar red\n"
                               "element face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0 200\n1 0 0 100\n0 1 0 50\n3 0 1 2\n"));
  EXPECT_EQ(describe_unwritten("red.off", r.attributes).size(), 1u);
}

TEST_F(ColorFidelity, describe_unwritten_names_what_each_format_cannot_hold) {
  MeshAttributes a;
  EXPECT_TRUE(describe_unwritten("x.stl", a).empty());
  a.vertex_colors = {Rgba{}};
  a.face_colors = {Rgba{}};
  a.face_groups = {{"g part", 0}};
  a.texture_coordinates = 3;
  a.normals = 1;
  a.double_precision = true;
  EXPECT_EQ(describe_unwritten("x.obj", a),
            (std::vector<std::string>{
                "3 texture coordinates (vt) and 1 normal (vn) not written: they were not kept "
                "(read without them)",
                "face colours not written: OBJ holds none"}));
  EXPECT_EQ(describe_unwritten("x.ply", a).size(), 2u);  // vt/vn, groups
  EXPECT_EQ(
      describe_unwritten("x.stl", a),
      (std::vector<std::string>{
          "3 texture coordinates (vt) and 1 normal (vn) not written: STL holds none per corner "
          "(write OBJ to keep them)",
          "vertex colours not written: STL holds none", "face colours not written: STL holds none",
          "OBJ groups and materials not written (1 o/g/usemtl line, 0 mtllib lines): STL "
          "holds none"}));
  // What only the mesh tells: positions that are no float, colours of welded vertices.
  Soup soup;
  soup.positions = {Point(0.1, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  soup.add_polygon({0, 1, 2});
  const WrittenOutput stl = describe_written("x.stl", soup, a, 2);
  EXPECT_EQ(stl.triangles, 1u);
  EXPECT_EQ(stl.left_out.back(),
            "positions of 1 vertex rounded to 32-bit floats: STL holds no more");
  EXPECT_EQ(stl.left_out[stl.left_out.size() - 2],
            "colours of 2 welded vertices not written: each takes the colour of the vertex it "
            "welded into");
  EXPECT_EQ(describe_written("x.ply", soup, MeshAttributes()).left_out.size(), 0u);
}

TEST_F(ColorFidelity, obj_colors_written_0_to_255_are_read_as_such) {
  const Reading r = read(write("bytes.obj",
                               "v 0 0 0 255 128 0\nv 1 0 0 0.5 0.25 1\nv 0 1 0\n"
                               "v 0 0 1 1 1 1\n" +
                                   std::string(kTetrahedronFaces)));
  const auto& c = r.attributes.vertex_colors;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], (Rgba{255, 128, 0, 255}));  // was clamped to yellow (255, 255, 0)
  // In a file with a 0..255 colour, "1 1 1" is near black (it was white); "0.5 0.25 1" has
  // fractions: 0..1 in any file.
  EXPECT_EQ(c[1], (Rgba{128, 64, 255, 255}));
  EXPECT_EQ(c[3], (Rgba{1, 1, 1, 255}));
  // A value above 1 with a fraction is a 0..1 colour out of range: clamped and counted, and the
  // file's other colours keep their 0..1 scale.
  const Reading over = read(write("over.obj",
                                  "v 0 0 0 1.5 0 0\nv 1 0 0 0 1 0\nv 0 1 0\n"
                                  "v 0 0 1 0.5 0.5 0.5\n" +
                                      std::string(kTetrahedronFaces)));
  EXPECT_EQ(over.attributes.vertex_colors[0], (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(over.attributes.vertex_colors[1], (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(over.attributes.vertex_colors[3], (Rgba{128, 128, 128, 255}));
  ASSERT_EQ(over.attributes.not_kept.size(), 1u);
  EXPECT_EQ(over.attributes.not_kept[0].count, 1u);
  EXPECT_TRUE(over.attributes.not_kept[0].clamped);
  // A file of 0..1 colours only keeps the 0..1 scale.
  const Reading unit = read(write("unit.obj",
                                  "v 0 0 0 1 0.5 0\nv 1 0 0 0.5 0.25 1\nv 0 1 0\n"
                                  "v 0 0 1 1 1 1\n" +
                                      std::string(kTetrahedronFaces)));
  EXPECT_EQ(unit.attributes.vertex_colors[0], (Rgba{255, 128, 0, 255}));
  EXPECT_EQ(unit.attributes.vertex_colors[3], (Rgba{255, 255, 255, 255}));
}

TEST_F(ColorFidelity, what_a_reader_reads_past_is_named_for_every_output) {
  const auto not_kept_of = [this](const std::string& name, const std::string& bytes) {
    return read(write(name, bytes)).attributes.not_kept;
  };
  // PLY: vertex normals and texture coordinates, a face property, an element of its own.
  const auto ply = not_kept_of(
      "uv.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float s\nelement face 1\n"
      "property list uchar int vertex_indices\nproperty int flags\nelement material 2\n"
      "property uchar red\nend_header\n0 0 0 1 0\n1 0 0 1 1\n0 1 0 1 0\n3 0 1 2 7\n1\n2\n");
  ASSERT_EQ(ply.size(), 3u);
  EXPECT_EQ(ply[0].what, "PLY vertex properties nx, s");
  EXPECT_EQ(ply[0].count, 3u);
  EXPECT_EQ(ply[1].what, "PLY face property flags");
  EXPECT_EQ(ply[2].what, "PLY element 'material'");
  EXPECT_EQ(ply[2].count, 2u);
  // OFF: normals (NOFF), values after a plain OFF vertex, a face colour of 2 values.
  const auto off = not_kept_of("n.off",
                               "NOFF\n3 1 0\n0 0 0 0 0 1 0.5\n1 0 0 0 0 1\n0 1 0 0 0 1\n"
                               "3 0 1 2 0.1 0.2\n");
  ASSERT_EQ(off.size(), 3u);
  EXPECT_EQ(off[0].what, "OFF vertex normals (NOFF)");
  EXPECT_EQ(off[1].count, 1u);  // the vertex line with 0.5 after its normal
  EXPECT_EQ(off[2].count, 1u);  // the face with 2 values after its corners
  // OBJ: a w other than 1.
  const auto obj = not_kept_of("w.obj", "v 0 0 0 2\nv 1 0 0 1\nv 0 1 0\nf 1 2 3\n");
  ASSERT_EQ(obj.size(), 1u);
  EXPECT_EQ(obj[0].what, "OBJ vertex w other than 1");
  EXPECT_EQ(obj[0].count, 1u);
  // OBJ: colour values outside their range, clamped (a 0-255 colour above 255, a negative one).
  const auto clamped =
      not_kept_of("clamp.obj", "v 0 0 0 300 0 0\nv 1 0 0 0.5 -0.25 1\nv 0 1 0 0 0 1\nf 1 2 3\n");
  ASSERT_EQ(clamped.size(), 1u);
  EXPECT_EQ(clamped[0].what,
            "OBJ vertex colour values outside 0-1 (or 0-255) or not finite, clamped to the range");
  EXPECT_EQ(clamped[0].count, 2u);
  // Binary STL: triangles whose attribute word is not 0.
  std::string stl(80, ' ');
  const std::uint32_t two = 2;
  stl.append(reinterpret_cast<const char*>(&two), 4);
  for (int t = 0; t < 2; ++t) {
    const float values[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, float(t)};
    stl.append(reinterpret_cast<const char*>(values), sizeof values);
    const std::uint16_t attribute = t == 0 ? 0x7C00 : 0;  // red in the VisCAM/SolidView scheme
    stl.append(reinterpret_cast<const char*>(&attribute), 2);
  }
  const auto facets = not_kept_of("a.stl", stl);
  ASSERT_EQ(facets.size(), 1u);
  EXPECT_EQ(facets[0].count, 1u);
  // Facet normals against the winding (a zero normal makes no claim), binary and ASCII.
  std::string flipped(80, ' ');
  const std::uint32_t three = 3;
  flipped.append(reinterpret_cast<const char*>(&three), 4);
  for (float z : {-1.0f, 0.0f, 1.0f}) {
    const float values[12] = {0, 0, z, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    flipped.append(reinterpret_cast<const char*>(values), sizeof values);
    flipped.append(2, '\0');
  }
  const auto reversed = not_kept_of("flipped.stl", flipped);
  ASSERT_EQ(reversed.size(), 1u);
  EXPECT_EQ(reversed[0].what,
            "STL facet normals against the winding of their corners (written ones follow the "
            "winding)");
  EXPECT_EQ(reversed[0].count, 1u);
  const auto reversed_ascii =
      not_kept_of("flipped_ascii.stl",
                  "solid\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                  "vertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
                  "vertex 1 0 0\nvertex 0 1 1\nendloop\nendfacet\nendsolid\n");
  ASSERT_EQ(reversed_ascii.size(), 1u);
  EXPECT_EQ(reversed_ascii[0].count, 1u);
  // ASCII STL solid names, a binary STL header colour, PLY comments.
  const auto named = not_kept_of("named.stl",
                                 "solid part A\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                                 "vertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  ASSERT_EQ(named.size(), 1u);
  EXPECT_EQ(named[0].what, "ASCII STL solid names");
  std::string colored = stl;
  colored.replace(0, 10, "COLOR=\x80\x80\x80\xff");
  EXPECT_EQ(not_kept_of("colour.stl", colored).back().what,
            "binary STL header colour (COLOR=/MATERIAL=)");
  const auto comments = not_kept_of(
      "c.ply",
      "ply\nformat ascii 1.0\ncomment TextureFile tex.png\ncomment written by MeshBridge\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ASSERT_EQ(comments.size(), 1u);
  EXPECT_EQ(comments[0].count, 1u);  // MeshBridge's own comment is not counted
  // Bytes after the last element of a binary PLY (a false count would hide faces there).
  std::string binary_ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary_ply.append(reinterpret_cast<const char*>(corners), sizeof corners);
  const std::int32_t face[3] = {0, 1, 2};
  binary_ply += '\3';
  binary_ply.append(reinterpret_cast<const char*>(face), sizeof face);
  EXPECT_TRUE(not_kept_of("exact.ply", binary_ply).empty());
  ReadInfo exact, tail;
  read_soup(write("exact.ply", binary_ply), &exact);
  EXPECT_EQ(exact.trailing_bytes, 0u);
  EXPECT_FALSE(exact.changed_anything());
  // Counted in the reading itself (check reads no attributes and still warns).
  read_soup(write("tail.ply", binary_ply + '\3' + std::string(12, '\0')), &tail);
  EXPECT_EQ(tail.trailing_bytes, 13u);
  EXPECT_TRUE(tail.changed_anything());
  EXPECT_NE(describe_reading(tail).find("13 bytes after the end of the mesh not read (padding, "
                                        "or items a false count leaves out)"),
            std::string::npos)
      << describe_reading(tail);
  EXPECT_TRUE(not_kept_of("tail.ply", binary_ply + '\3' + std::string(12, '\0')).empty());
  // Named for every output, even the format the file came in.
  MeshAttributes a;
  a.not_kept = ply;
  EXPECT_EQ(describe_unwritten("x.ply", a).front(),
            "PLY vertex properties nx, s, on 3 vertices: not written (MeshBridge reads past them)");
}

TEST_F(ColorFidelity, obj_group_lines_after_the_last_face_are_written_back) {
  const Reading r = read(write("trailing.obj",
                               "g a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                               "g trailing\nusemtl unused\n"));
  const std::vector<std::string> lines = lines_of(write_back(r, "trailing_out.obj"));
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[4], "g a");
  EXPECT_EQ(lines[5], "f 1 2 3");
  EXPECT_EQ(lines[6], "g trailing");
  EXPECT_EQ(lines[7], "usemtl unused");
}

TEST_F(ColorFidelity, write_mesh_refuses_missing_flags_of_another_size) {
  IndexedMesh mesh;
  mesh.soup = read_soup(write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  MeshAttributes a;
  a.vertex_colors.assign(3, Rgba{});
  a.vertex_color_missing = {true};
  EXPECT_THROW(write_mesh(path("t.ply"), mesh, &a), WriteError);
}

}  // namespace
}  // namespace meshbridge
