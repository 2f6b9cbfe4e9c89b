// SPDX-License-Identifier: GPL-3.0-or-later
// The STL writer: binary (default) or ascii triangles; polygons are cut into triangles by ear
// clipping (triangulate_polygon()), each facet gets its unit normal (0 0 0 for a zero-area one).
// STL has no shared vertices and only 32-bit floats in binary: a reader welds by position again.
#include "geometry/triangulate.h"
#include "io/formats.h"
#include "io/text_output.h"

#include "meshbridge/errors.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

Point unit_normal(const Point& a, const Point& b, const Point& c) {
  const Point n = (b - a) % (c - a);  // OpenMesh's cross product
  const double length = n.norm();
  return length > 0 && std::isfinite(length) ? n / length : Point(0, 0, 0);
}

std::uint64_t triangle_count(const Soup& soup) {
  std::uint64_t triangles = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    triangles += polygon_triangle_count(soup, f);
  return triangles;
}

//! Calls `triangle(a, b, c)` for every triangle of the polygons (triangulate_polygon()), in
//! face order.
template <class Triangle>
void for_each_triangle(const Soup& soup, Triangle triangle) {
  Triangulation t;
  avoid_existing_edges(soup, t);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (soup.arity(f) == 3) {
      const PolygonView p = soup.polygon(f);
      triangle(soup.positions[p[0]], soup.positions[p[1]], soup.positions[p[2]]);
      continue;
    }
    triangulate_polygon(soup, f, t);
    for (const auto& [a, b, c] : t.triangles)
      triangle(soup.positions[a], soup.positions[b], soup.positions[c]);
  }
}

void put_u32(unsigned char* at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    at[i] = static_cast<unsigned char>(value >> (8 * i));
}

void put_float(unsigned char* at, double value) {
  const float f = static_cast<float>(value);
  std::uint32_t bits;
  std::memcpy(&bits, &f, 4);
  put_u32(at, bits);
}

//! The point stored as three little-endian floats at `at`.
Point stored_point(const unsigned char* at) {
  Point p;
  for (int i = 0; i < 3; ++i) {
    std::uint32_t bits = 0;
    for (int k = 0; k < 4; ++k)
      bits |= std::uint32_t(at[4 * i + k]) << (8 * k);
    float value;
    std::memcpy(&value, &bits, 4);
    p[i] = value;
  }
  return p;
}

}  // namespace

void require_float_range(const Soup& soup, const std::string& path, const char* format) {
  for (std::size_t v = 0; v < soup.positions.size(); ++v) {
    for (int i = 0; i < 3; ++i) {
      const double x = soup.positions[v][i];
      if (std::isinf(static_cast<float>(x))) {
        char number[32];
        char* end = std::to_chars(number, number + sizeof number, x).ptr;
        throw WriteError(path + ": vertex " + std::to_string(v) + " has coordinate " +
                         std::string(number, end) + ", beyond what the 32-bit floats of " + format +
                         " hold (at most 3.4e38): write PLY, OBJ or OFF, which keep it");
      }
    }
  }
}

void write_stl(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes*,
               const WriteOptions& options) {
  const Soup& soup = mesh.soup;
  const std::uint64_t triangles = triangle_count(soup);
  // Binary STL stores floats; ASCII STL readers (MeshBridge's too) take its numbers as floats.
  require_float_range(soup, out.target(), "STL");
  if (options.binary) {
    if (triangles > 0xFFFFFFFFu) {
      throw WriteError(out.target() + ": " + std::to_string(triangles) +
                       " triangles do not fit a binary STL (at most 2^32 - 1)");
    }
    unsigned char head[84] = {};
    const char title[] = "MeshBridge binary STL";  // never "solid...": readers would guess ascii
    std::memset(head, ' ', 80);
    std::memcpy(head, title, sizeof title - 1);
    put_u32(head + 80, static_cast<std::uint32_t>(triangles));
    out.write(head, sizeof head);
    constexpr std::size_t kPerBlock = 20000;  // 1 MB
    std::vector<unsigned char> block(50 * kPerBlock);
    std::size_t used = 0;
    for_each_triangle(soup, [&](const Point& a, const Point& b, const Point& c) {
      unsigned char* r = block.data() + 50 * used;
      const Point* corners[3] = {&a, &b, &c};
      for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < 3; ++i)
          put_float(r + 12 + 12 * k + 4 * i, (*corners[k])[i]);
      }
      // The normal of the corners as stored (32-bit floats), read back from the bytes: writing
      // what a binary STL reader gets back then gives the same bytes. (Not through a
      // double -> float -> double cast: GCC 12's SLP vectorizer drops that rounding in some
      // lanes at -O2 and -O3.)
      const Point n = unit_normal(stored_point(r + 12), stored_point(r + 24), stored_point(r + 36));
      for (int i = 0; i < 3; ++i)
        put_float(r + 4 * i, n[i]);
      r[48] = r[49] = 0;
      if (++used == kPerBlock) {
        out.write(block.data(), 50 * used);
        used = 0;
      }
    });
    out.write(block.data(), 50 * used);
    return;
  }
  TextOutput text(out);
  const auto vector = [&](const Point& p) {
    text.number(p[0]).ch(' ').number(p[1]).ch(' ').number(p[2]).ch('\n');
  };
  text.text("solid meshbridge\n");
  for_each_triangle(soup, [&](const Point& a, const Point& b, const Point& c) {
    text.text("facet normal ");
    vector(unit_normal(a, b, c));
    text.text(" outer loop\n");
    for (const Point* p : {&a, &b, &c}) {
      text.text("  vertex ");
      vector(*p);
    }
    text.text(" endloop\nendfacet\n");
  });
  text.text("endsolid meshbridge\n");
  text.flush();
}

}  // namespace meshbridge::detail
