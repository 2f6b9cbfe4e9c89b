// SPDX-License-Identifier: GPL-3.0-or-later
// The model part of a 3MF read as it is inflated, chunk by chunk (src/io/mesh_stream_3mf.cpp,
// src/io/inflate_chunks.cpp), gives exactly what the part read whole gives (read_meshes_xml():
// the same meshes, the same part for lib3mf), wherever the chunk borders cut the text; and says
// so, rather than guess, where the scan gives up or the stream is broken.

#include "io/inflate_chunks.h"
#include "io/mesh_stream_3mf.h"
#include "io/mesh_xml_3mf.h"

#include <gtest/gtest.h>
#include <libdeflate.h>

#include <cstdint>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace meshbridge::detail {
namespace {

constexpr std::size_t kChunk = std::size_t(1) << 18;  // inflate_chunks.cpp's chunk

struct Deflated {
  std::vector<unsigned char> bytes;
  std::uint32_t crc = 0;
};

Deflated deflate(const std::string& text) {
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(6);
  Deflated d;
  d.bytes.resize(libdeflate_deflate_compress_bound(compressor, text.size()));
  d.bytes.resize(libdeflate_deflate_compress(compressor, text.data(), text.size(), d.bytes.data(),
                                             d.bytes.size()));
  libdeflate_free_compressor(compressor);
  d.crc = libdeflate_crc32(0, text.data(), text.size());
  return d;
}

const char* kHead = R"(<?xml version="1.0" encoding="UTF-8"?>)"
                    "\n"
                    R"(<model unit="millimeter" xmlns="http://schemas.microsoft.com/)"
                    R"(3dmanufacturing/core/2015/02">)";

// Object `id`: `vertices` vertices written with random spacing and quotes, then as many
// triangles; `oddity` (if any) put in the vertex list after `vertices / 2` vertices.
std::string object(int id, int vertices, std::mt19937& random, const std::string& oddity = "") {
  const char* spaces[] = {" ", "\n", "\r\n", "\t", "  ", "\n    "};
  const auto space = [&] { return std::string(spaces[random() % 6]); };
  const auto number = [&] {
    const int whole = int(random() % 2000) - 1000;
    return std::to_string(whole) + "." + std::to_string(random() % 1000000);
  };
  std::string s = "<object id=\"" + std::to_string(id) + "\" type=\"model\"><mesh><vertices>";
  for (int v = 0; v < vertices; ++v) {
    if (v == vertices / 2)
      s += oddity;
    const char quote = random() % 4 == 0 ? '\'' : '"';
    s += space() + "<vertex x=" + quote + number() + quote + space() + "y=" + quote + number() +
         quote + " z=" + quote + number() + quote + (random() % 2 ? "/>" : " />");
  }
  s += "</vertices>" + space() + "<triangles>";
  for (int t = 0; t < vertices; ++t) {
    s += space() + "<triangle v1=\"" + std::to_string(t) + "\" v2=\"" +
         std::to_string((t + 1) % vertices) + "\" v3=\"" + std::to_string((t + 7) % vertices) +
         "\"/>";
  }
  return s + "</triangles></mesh></object>\n";
}

std::string model(const std::string& padding, const std::vector<std::string>& objects) {
  std::string s = std::string(kHead) + "<metadata name=\"Title\">" + padding + "</metadata>";
  s += "<resources>";
  for (const std::string& o : objects)
    s += o;
  s += R"(<object id="99" type="model"><components><component objectid="1"/></components>)";
  return s + "</object></resources><build><item objectid=\"99\"/></build></model>";
}

// Reads `text` both ways; true if the streamed read took it (and then expects the same).
bool expect_same_as_whole(const std::string& text) {
  std::map<std::uint32_t, MeshXml> whole, streamed;
  std::string whole_stripped, streamed_stripped;
  EXPECT_TRUE(read_meshes_xml(text, whole, whole_stripped));
  const Deflated d = deflate(text);
  if (!read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size(), d.crc, streamed,
                            streamed_stripped)) {
    EXPECT_TRUE(streamed.empty());
    return false;
  }
  EXPECT_EQ(streamed.size(), whole.size());
  for (const auto& [id, mesh] : whole) {
    SCOPED_TRACE("object " + std::to_string(id));
    if (streamed.count(id) != 1) {
      ADD_FAILURE() << "not read as the part streamed";
      continue;
    }
    EXPECT_EQ(streamed.at(id).positions, mesh.positions);
    EXPECT_EQ(streamed.at(id).corners, mesh.corners);
  }
  EXPECT_EQ(streamed_stripped, whole_stripped);
  return true;
}

TEST(Format3mfStream, parts_of_many_chunks_read_as_the_whole_part) {
  if (!can_inflate_in_chunks())
    GTEST_SKIP() << "built without ISA-L";
  std::mt19937 random(16);
  std::vector<std::string> objects;
  for (int id = 1; id <= 3; ++id)
    objects.push_back(object(id, 12000, random));
  const std::string text = model("T", objects);
  ASSERT_GT(text.size(), 5 * kChunk);       // many borders, in every kind of place
  for (const char* threads : {"1", "2"}) {  // inflated on this thread, and on a second one
    SCOPED_TRACE(std::string("threads ") + threads);
    setenv("MESHBRIDGE_THREADS", threads, 1);
    EXPECT_TRUE(expect_same_as_whole(text));
    unsetenv("MESHBRIDGE_THREADS");
  }
  std::map<std::uint32_t, MeshXml> meshes;
  std::string stripped;
  const Deflated d = deflate(text);
  ASSERT_TRUE(
      read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size(), d.crc, meshes, stripped));
  ASSERT_EQ(meshes.size(), 3u);
  EXPECT_EQ(meshes.at(2).positions.size(), 12000u);
  EXPECT_EQ(meshes.at(3).corners.size(), 3u * 12000);
  EXPECT_EQ(stripped.find("<vertex "), std::string::npos);
}

TEST(Format3mfStream, every_border_offset_around_the_end_of_a_list_reads_the_same) {
  if (!can_inflate_in_chunks())
    GTEST_SKIP() << "built without ISA-L";
  // The first chunk border swept over 140 bytes around "</vertices> <triangles>" by the length
  // of the title before the lists: inside a vertex, a number, a quote, the end tag, the start
  // tag, the first triangles.
  std::mt19937 random(4);
  const std::string one = object(1, 4000, random);
  const std::size_t base = model("", {one}).find("</vertices>");
  ASSERT_LT(base + 70, kChunk);
  int taken = 0;
  for (std::size_t shift = 0; shift < 140; ++shift) {
    SCOPED_TRACE("border " + std::to_string(shift) + " bytes after 70 before the end tag");
    const std::string text = model(std::string(kChunk - base - 70 + shift, 'p'), {one});
    ASSERT_EQ(text.find("</vertices>") + 70, kChunk + shift);
    taken += expect_same_as_whole(text) ? 1 : 0;
    if (HasFailure())
      break;
  }
  EXPECT_EQ(taken, 140);
}

TEST(Format3mfStream, gives_up_where_the_scan_does_and_on_a_broken_stream) {
  if (!can_inflate_in_chunks())
    GTEST_SKIP() << "built without ISA-L";
  std::mt19937 random(7);
  // A comment deep in the third list: pugixml decides that one, on the part read whole.
  const std::string odd = model("T", {object(1, 8000, random), object(2, 8000, random),
                                      object(3, 8000, random, "<!-- a comment -->")});
  EXPECT_FALSE(expect_same_as_whole(odd));
  // A broken stream: cut short, a wrong CRC, a wrong size.
  const std::string text = model("T", {object(1, 8000, random)});
  const Deflated d = deflate(text);
  std::map<std::uint32_t, MeshXml> meshes;
  std::string stripped;
  EXPECT_TRUE(
      read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size(), d.crc, meshes, stripped));
  EXPECT_FALSE(read_meshes_streamed(d.bytes.data(), d.bytes.size() / 2, text.size(), d.crc, meshes,
                                    stripped));
  EXPECT_TRUE(meshes.empty());
  EXPECT_FALSE(read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size(), d.crc ^ 1u, meshes,
                                    stripped));
  EXPECT_FALSE(read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size() - 1, d.crc, meshes,
                                    stripped));
  EXPECT_FALSE(read_meshes_streamed(d.bytes.data(), d.bytes.size(), text.size() + 1, d.crc, meshes,
                                    stripped));
}

}  // namespace
}  // namespace meshbridge::detail
