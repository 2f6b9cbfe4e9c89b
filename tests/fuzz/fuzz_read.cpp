// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes -> a file -> read_soup, the command-line tool's loading path through
// OpenMesh's readers. The first byte chooses the extension (obj, off, ply, stl; bit 2: upper
// case); the rest is the file. read_soup may only throw ReadError or InvalidSoupError; a soup it
// returns must be valid and repair with every invariant holding, and the repaired mesh must be
// written and read back with no singular element. Anything else aborts.
#include "fuzz_invariants.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/validate.h"

#include <unistd.h>
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
  const std::string path = kBase + "." + kExtensions[data[0] % 8];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  Soup soup;
  bool read = false;
  try {
    ReadInfo info;
    soup = read_soup(path, &info);
    read = true;
    fuzz::check(info.faces_dropped_by_reader <= info.declared_faces, "dropped > declared");
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
  // Through a file and back: OpenMesh's writer and reader keep the repair.
  const std::string out = kBase + "_out.ply";
  try {
    write_mesh(out, result.mesh);
  } catch (const WriteError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    fuzz::fail("write_mesh failed on a repaired mesh");
  }
  Soup back;
  try {
    back = read_soup(out);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
    fuzz::fail("a written mesh does not read back");
  }
  std::remove(out.c_str());
  fuzz::check(back.num_faces() == result.mesh.soup.num_faces(), "faces lost writing");
  fuzz::check(back.corner_vertices == result.mesh.soup.corner_vertices, "corners changed writing");
  const DefectReport after = detect_defects(back);
  fuzz::check(after.singular_edges.empty() && after.num_singular_vertices() == 0,
              "written mesh reads back non-manifold");
  return 0;
}
