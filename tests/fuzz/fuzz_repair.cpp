// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target: bytes -> a polygon soup (coincident and duplicate positions, arities 0..8,
// repeated and out-of-range indices, sometimes NaN or infinity) -> validate_soup; a soup it
// accepts goes through detect_defects and repair with options taken from the bytes, and every
// invariant of the repair is checked (fuzz_invariants.h), including that repairing the result
// again changes nothing. A soup validate_soup rejects must be rejected the same way by
// detect_defects and repair. Any other exception, or a violated invariant, aborts.
//
// Input layout (little-endian; missing bytes end the soup where they run out):
//   byte 0     options: bit 0 combinatorial pairing, 1 no orientation, 2 no stitching,
//              3 cut non-orientable, 4 remove duplicates, 5 remove degenerate,
//              6 remove isolated vertices, 7 no detection before/after
//   u16        vertex count (low 15 bits, at most 1024); the top bit turns gap closing on at
//              the automatic tolerance (off otherwise)
//   per vertex a mode byte m, then by m % 4:
//              0: 3 x int8 (grid positions: exact ties, coincident and coplanar faces)
//              1: 3 x float32 (anything, NaN and infinity included)
//              2: u16 k: the position of vertex k % (this index + 1) again (coincident)
//              3: 3 x int8 times 1e-6 * (m >> 2) (near-coincident positions)
//   u16        face count (at most 1024)
//   per face   an arity byte a (a % 9 corners), then per corner a u16 i: 0xFFFF is the
//              no-index marker, 0xFFFE repeats the previous corner, anything else is a vertex
//              index as written (out of range when >= the vertex count)
#include "fuzz_invariants.h"

#include "meshbridge/errors.h"
#include "meshbridge/validate.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

using namespace meshbridge;

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() {
    const std::uint16_t low = u8();
    return static_cast<std::uint16_t>(low | (u8() << 8));
  }
  float f32() {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
      bits |= std::uint32_t(u8()) << (8 * i);
    float x;
    std::memcpy(&x, &bits, 4);
    return x;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

struct Input {
  Soup soup;
  RepairOptions options;
};

Input decode(const std::uint8_t* data, std::size_t size) {
  Bytes bytes(data, size);
  Input input;
  const std::uint8_t flags = bytes.u8();
  RepairOptions& o = input.options;
  o.pairing = flags & 1 ? PairingPolicy::combinatorial : PairingPolicy::geometric;
  o.orient = !(flags & 2);
  o.stitch = !(flags & 4);
  o.cut_nonorientable = flags & 8;
  o.remove_duplicate_faces = flags & 16;
  o.remove_degenerate_faces = flags & 32;
  o.remove_isolated_vertices = flags & 64;
  o.detect_before_after = !(flags & 128);

  Soup& soup = input.soup;
  const std::uint16_t vertex_word = bytes.u16();
  const std::size_t vertices = (vertex_word & 0x7FFF) % 1025;
  // Gap closing off, or on the top bit at the automatic tolerance (as users get it); with the
  // near-coincident vertex mode below it welds and closes T-junctions.
  if (!(vertex_word & 0x8000))
    o.close_gaps.tolerance = 0;
  for (std::size_t v = 0; v < vertices && !bytes.empty(); ++v) {
    const std::uint8_t mode = bytes.u8();
    Point p(0, 0, 0);
    switch (mode % 4) {
      case 0:
        for (int i = 0; i < 3; ++i)
          p[i] = static_cast<std::int8_t>(bytes.u8());
        break;
      case 1:
        for (int i = 0; i < 3; ++i)
          p[i] = bytes.f32();
        break;
      case 2: {
        const std::size_t k = bytes.u16() % (v + 1);
        if (k < v)
          p = soup.positions[k];
        break;
      }
      default:
        for (int i = 0; i < 3; ++i)
          p[i] = static_cast<std::int8_t>(bytes.u8()) * 1e-6 * (mode >> 2);
        break;
    }
    soup.add_vertex(p);
  }
  const std::size_t faces = bytes.u16() % 1025;
  std::vector<Index> polygon;
  for (std::size_t f = 0; f < faces && !bytes.empty(); ++f) {
    const std::size_t arity = bytes.u8() % 9;
    polygon.clear();
    for (std::size_t c = 0; c < arity; ++c) {
      const std::uint16_t i = bytes.u16();
      if (i == 0xFFFF)
        polygon.push_back(kNoIndex);
      else if (i == 0xFFFE && !polygon.empty())
        polygon.push_back(polygon.back());
      else
        polygon.push_back(i);
    }
    soup.add_polygon(polygon);
  }
  return input;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input input = decode(data, size);
  try {
    validate_soup(input.soup);
  } catch (const InvalidSoupError&) {
    // Rejected input must be rejected by every entry point, never half-processed.
    try {
      detect_defects(input.soup);
      fuzz::fail("detect_defects accepted a soup validate_soup rejects");
    } catch (const InvalidSoupError&) {
    }
    try {
      repair(input.soup, input.options);
      fuzz::fail("repair accepted a soup validate_soup rejects");
    } catch (const InvalidSoupError&) {
    }
    return 0;
  }
  const DefectReport before = detect_defects(input.soup);
  fuzz::check(before.num_faces == input.soup.num_faces(), "detect_defects: face count");
  fuzz::check(before.num_vertices == input.soup.num_vertices(), "detect_defects: vertex count");
  const RepairResult result = repair(input.soup, input.options);
  fuzz::check_repair(input.soup, input.options, result);
  if (input.options.detect_before_after) {
    fuzz::check(result.report.before.singular_edges.size() == before.singular_edges.size(),
                "report.before differs from detect_defects");
    fuzz::check(result.report.before.num_components == before.num_components,
                "report.before differs from detect_defects");
  }
  // Deterministic, and the consuming repair (which returns a soup it leaves unchanged as it is,
  // without the pipeline) gives the same mesh and counts.
  const RepairResult again = repair(Soup(input.soup), input.options);
  const IndexedMesh& m = again.mesh;
  fuzz::check(m.soup.corner_vertices == result.mesh.soup.corner_vertices &&
                  m.soup.face_begin == result.mesh.soup.face_begin &&
                  m.soup.positions == result.mesh.soup.positions &&
                  m.vertex_origin == result.mesh.vertex_origin &&
                  m.face_origin == result.mesh.face_origin &&
                  m.corner_origin == result.mesh.corner_origin,
              "repair is not deterministic, or repair(Soup&&) differs from repair(const Soup&)");
  const RepairReport& r = again.report;
  const RepairReport& q = result.report;
  fuzz::check(
      r.faces_out == q.faces_out && r.vertices_out == q.vertices_out &&
          r.faces_flipped == q.faces_flipped && r.vertices_split == q.vertices_split &&
          r.sides_cut == q.sides_cut && r.sides_stitched == q.sides_stitched &&
          r.components_after == q.components_after && r.after.watertight == q.after.watertight &&
          r.gaps.tolerance == q.gaps.tolerance && r.gaps.vertices_welded == q.gaps.vertices_welded,
      "repair(Soup&&) reports other counts than repair(const Soup&)");
  fuzz::check_idempotent(input.options, result);
  return 0;
}
