// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file soup.h
//! The polygon soup: positions and polygons exactly as read, before any topology.

#include <OpenMesh/Core/Geometry/VectorT.hh>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <vector>

namespace meshbridge {

//! Vertex and face indices are 32-bit: meshes up to 4 billion elements, half the memory of size_t.
using Index = std::uint32_t;
//! Marks "no element" in index tables (unpaired side, no origin, ...).
inline constexpr Index kNoIndex = static_cast<Index>(-1);

//! Positions are always double in the core; adapters convert.
using Point = OpenMesh::Vec3d;

//! A read-only view of one polygon's vertex indices (a C++17 stand-in for std::span).
struct PolygonView {
  const Index* first = nullptr;
  const Index* last = nullptr;
  const Index* begin() const { return first; }
  const Index* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
  Index operator[](std::size_t i) const { return first[i]; }
};

//! An indexed face set of any arity, stored compactly (no per-face allocation).
//!
//! Polygon f has the corners `corner_vertices[face_begin[f] .. face_begin[f+1])`; corner c of the
//! soup is the c-th entry of `corner_vertices`. Polygon *side* c runs from corner c to the next
//! corner of the same polygon (cyclically), so sides and corners share their numbering.
//! A Soup may hold anything; `validate_soup()` states what the algorithms accept.
class Soup {
 public:
  std::vector<Point> positions;        //!< #V positions
  std::vector<Index> corner_vertices;  //!< #C vertex indices, polygons back to back
  std::vector<Index> face_begin{0};    //!< #F+1 offsets into corner_vertices

  std::size_t num_vertices() const { return positions.size(); }
  std::size_t num_faces() const { return face_begin.size() - 1; }
  std::size_t num_corners() const { return corner_vertices.size(); }

  Index add_vertex(const Point& p) {
    positions.push_back(p);
    return static_cast<Index>(positions.size() - 1);
  }
  //! Appends a polygon; returns its face index. Indices are not checked here (see validate_soup).
  template <class Range>
  Index add_polygon(const Range& vertices) {
    for (Index v : vertices)
      corner_vertices.push_back(v);
    face_begin.push_back(static_cast<Index>(corner_vertices.size()));
    return static_cast<Index>(num_faces() - 1);
  }
  Index add_polygon(std::initializer_list<Index> vertices) {
    return add_polygon<std::initializer_list<Index>>(vertices);
  }
  //! Appends a copy of a polygon, which may be one of this soup's own.
  Index add_polygon(PolygonView polygon) {
    const std::less<const Index*> less;
    const Index* data = corner_vertices.data();
    if (!less(polygon.first, data) && less(polygon.first, data + corner_vertices.size())) {
      const std::vector<Index> copy(polygon.begin(), polygon.end());  // push_back may reallocate
      return add_polygon<std::vector<Index>>(copy);
    }
    return add_polygon<PolygonView>(polygon);
  }

  PolygonView polygon(std::size_t f) const {
    const Index* base = corner_vertices.data();
    return {base + face_begin[f], base + face_begin[f + 1]};
  }
  std::size_t arity(std::size_t f) const { return face_begin[f + 1] - face_begin[f]; }
  //! Corner after corner c in its polygon f (cyclic).
  Index next_corner(Index c, std::size_t f) const {
    return c + 1 == face_begin[f + 1] ? face_begin[f] : c + 1;
  }

  void reserve(std::size_t vertices, std::size_t faces, std::size_t corners) {
    positions.reserve(vertices);
    face_begin.reserve(faces + 1);
    corner_vertices.reserve(corners);
  }
  void clear() {
    positions.clear();
    corner_vertices.clear();
    face_begin.assign(1, 0);
  }
};

}  // namespace meshbridge
