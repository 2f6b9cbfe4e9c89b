// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes -> a file -> read_soup, the command-line tool's loading path through
// MeshBridge's own readers (core/src/io/). The first byte chooses the reader by extension (bits
// 0-1: obj, off, ply, stl; bit 2: upper case) and the writer of the round trip (bits 3-4); the
// rest is the file. read_soup may only throw ReadError or InvalidSoupError; the accounting must
// add up (every record kept, split or set aside); a soup it returns must be valid and repair
// with every invariant holding, and the repaired mesh must be written (with the colours read)
// and read back unchanged with no singular element. Anything else aborts.
#include "fuzz_invariants.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/validate.h"

#include <unistd.h>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

// Where each input is written. The path reaches libFuzzer's table of compared bytes (through the
// intercepted memcmp/strcmp of the readers), so a reproducible run (scripts/fuzz.sh with
// FUZZ_RUNS sets MESHBRIDGE_FUZZ_SCRATCH_ID) uses a fixed name; otherwise the pid keeps parallel
// jobs apart.
std::string scratch_base() {
  const char* id = std::getenv("MESHBRIDGE_FUZZ_SCRATCH_ID");
  return std::string("/tmp/meshbridge_fuzz_read_") +
         (id != nullptr && *id != '\0' ? std::string(id) : std::to_string(::getpid()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshbridge;
  if (size == 0)
    return 0;
  static const char* const kExtensions[] = {"obj", "off", "ply", "stl", "OBJ", "Off", "PLY", "STL"};
  static const std::string kBase = scratch_base();
  // MESHBRIDGE_FUZZ_READER=obj|off|ply|stl pins the reader (a campaign per reader).
  static const char* const kPinned = std::getenv("MESHBRIDGE_FUZZ_READER");
  const std::string path =
      kBase + "." + (kPinned != nullptr && *kPinned != '\0' ? kPinned : kExtensions[data[0] % 8]);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  Soup soup;
  MeshAttributes attributes;
  bool read = false;
  try {
    ReadInfo info;
    soup = read_soup(path, &info, &attributes);
    read = true;
    fuzz::check(info.faces_kept + info.faces_split + info.faces_set_aside == info.declared_faces,
                "kept + split + set aside != declared faces");
    fuzz::check(soup.num_faces() + info.faces_without_corners == info.declared_faces,
                "the soup's faces are not the file's records");
    fuzz::check(
        attributes.vertex_colors.empty() || attributes.vertex_colors.size() == soup.num_vertices(),
        "vertex colours do not match the vertices");
    fuzz::check(attributes.face_colors.empty() || attributes.face_colors.size() == soup.num_faces(),
                "face colours do not match the faces");
    fuzz::check(attributes.vertex_color_missing.empty() ||
                    attributes.vertex_color_missing.size() == attributes.vertex_colors.size(),
                "vertex missing-colour flags do not match the colours");
    fuzz::check(attributes.face_color_missing.empty() ||
                    attributes.face_color_missing.size() == attributes.face_colors.size(),
                "face missing-colour flags do not match the colours");
  } catch (const ReadError&) {
  } catch (const InvalidSoupError&) {
  }
  std::remove(path.c_str());
  if (!read)
    return 0;
  try {
    validate_soup(soup);
  } catch (const InvalidSoupError&) {
    fuzz::fail("read_soup returned a soup validate_soup rejects");
  }
  fuzz::check(soup.num_faces() > 0, "read_soup returned a soup without faces");
  const RepairResult result = repair(soup);
  fuzz::check_repair(soup, RepairOptions(), result);

  if (result.mesh.soup.num_faces() == 0)
    return 0;  // every polygon was set aside: nothing to write
  // Through a file and back, in the format bits 3-4 choose: the writer and reader keep the
  // repair (STL fans polygons into triangles and welds corners by position, so only its
  // triangle count is compared).
  static const char* const kOutputs[] = {"_out.obj", "_out.off", "_out.ply", "_out.stl"};
  const int output = (data[0] >> 3) % 4;
  const std::string out = kBase + kOutputs[output];
  // STL stores 32-bit floats: a coordinate beyond their range is refused, not written as inf.
  bool beyond_floats = false;
  for (const Point& p : result.mesh.soup.positions) {
    for (int i = 0; i < 3; ++i)
      beyond_floats = beyond_floats || std::isinf(static_cast<float>(p[i]));
  }
  try {
    write_mesh(out, result.mesh, &attributes);
  } catch (const WriteError& error) {
    if (output == 3 && beyond_floats)
      return 0;
    std::fprintf(stderr, "%s\n", error.what());
    fuzz::fail("write_mesh failed on a repaired mesh");
  }
  fuzz::check(!(output == 3 && beyond_floats), "STL written with a coordinate beyond floats");
  const WrittenOutput written = describe_written(out, result.mesh.soup, attributes);
  Soup back;
  MeshAttributes back_attributes;
  ReadInfo back_info;
  try {
    back = read_soup(out, &back_info, &back_attributes);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    fuzz::fail("a written mesh does not read back");
  }
  std::remove(out.c_str());
  // Colours read back cover their elements, and missing-colour flags their colours.
  const auto& b = back_attributes;
  fuzz::check(b.vertex_colors.empty() || b.vertex_colors.size() == back.num_vertices(),
              "vertex colours read back do not cover the vertices");
  fuzz::check(b.face_colors.empty() || b.face_colors.size() == back.num_faces(),
              "face colours read back do not cover the faces");
  fuzz::check(
      b.vertex_color_missing.empty() || b.vertex_color_missing.size() == b.vertex_colors.size(),
      "vertex missing-colour flags of another size");
  fuzz::check(b.face_color_missing.empty() || b.face_color_missing.size() == b.face_colors.size(),
              "face missing-colour flags of another size");
  if (output == 3) {
    std::size_t triangles = 0;
    for (std::size_t f = 0; f < result.mesh.soup.num_faces(); ++f)
      triangles += result.mesh.soup.arity(f) - 2;
    fuzz::check(back.num_faces() == triangles, "triangles lost writing STL");
    fuzz::check(written.triangles == triangles, "describe_written miscounts the STL triangles");
    return 0;
  }
  fuzz::check(back.num_faces() == result.mesh.soup.num_faces(), "faces lost writing");
  // A repaired mesh whose every face has vertices of its own and whose faces meet along
  // coincident edges reads back as a per-face-vertex file does: welded by position (named in
  // back_info). Only then may its corners differ.
  if (back_info.vertices_welded_by_position > 0)
    return 0;
  fuzz::check(back.corner_vertices == result.mesh.soup.corner_vertices, "corners changed writing");
  for (std::size_t v = 0; v < back.num_vertices() && v < result.mesh.soup.num_vertices(); ++v) {
    const Point& a = back.positions[v];
    const Point& b = result.mesh.soup.positions[v];
    for (int k = 0; k < 3; ++k) {
      // Text keeps every double exactly; PLY keeps at least float precision.
      fuzz::check(output < 2 ? a[k] == b[k] : static_cast<float>(a[k]) == static_cast<float>(b[k]),
                  "positions changed writing");
    }
  }
  const DefectReport after = detect_defects(back);
  fuzz::check(after.singular_edges.empty() && after.num_singular_vertices() == 0,
              "written mesh reads back non-manifold");
  return 0;
}
