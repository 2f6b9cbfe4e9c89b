// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ texture coordinates and normals through a repair: every output corner takes the vt/vn of
// the input corner it comes from (IndexedMesh::corner_origin), so the copies of a split vertex
// keep theirs; a corner repair inserted into a side (a midpoint split, a T-junction closed) is
// interpolated between the two corners of that side; a face hole filling added has none.

#include "io/formats.h"

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

namespace meshbridge::detail {

namespace {

using Record = std::array<double, 3>;

//! Where along the side from `a` to `b` the point `p` lies (0 at a, 1 at b), clamped; an exact
//! midpoint (as a midpoint split makes it) gives exactly 0.5.
double parameter_along(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.sqrnorm();
  if (!(length2 > 0))
    return 0.5;
  if ((a + b) * 0.5 == p)
    return 0.5;
  const double t = ((p - a) | ab) / length2;
  return t < 0 ? 0 : (t > 1 ? 1 : t);
}

//! The records carried to the output, and the ones interpolation adds (each made once).
class CornerCarrier {
 public:
  CornerCarrier(const CornerAttributes& input, const IndexedMesh& mesh, CornerAttributes& out)
      : input_(input), mesh_(mesh), out_(out) {}

  void carry() {
    const Soup& soup = mesh_.soup;
    const bool texture = !input_.corner_texture.empty(), normal = !input_.corner_normal.empty();
    if (texture)
      out_.corner_texture.resize(soup.num_corners(), kNoIndex);
    if (normal)
      out_.corner_normal.resize(soup.num_corners(), kNoIndex);
    for (std::size_t c = 0; c < soup.num_corners(); ++c) {
      const Index o = origin(c);
      if (texture)
        out_.corner_texture[c] = record_of(input_.corner_texture, o);
      if (normal)
        out_.corner_normal[c] = record_of(input_.corner_normal, o);
    }
    for (std::size_t f = 0; f < soup.num_faces(); ++f)
      interpolate_inserted(soup.face_begin[f], soup.face_begin[f + 1]);
  }

 private:
  Index origin(std::size_t c) const {
    return mesh_.corner_origin.empty() ? static_cast<Index>(c) : mesh_.corner_origin[c];
  }
  static Index record_of(const std::vector<Index>& records, Index origin) {
    return origin < records.size() ? records[origin] : kNoIndex;
  }

  // Repair inserts a corner into the side from corner a to corner b of a face with the origin of
  // a: a run of corners with one origin is the corner a and those inserted after it, then b; in
  // a face repair reversed (its input corners in decreasing order), the run ends with a and b
  // comes before it. A face whose order tells neither (fewer than 3 corners of their own) keeps
  // the copies of a.
  void interpolate_inserted(Index first, Index last) {
    const Index n = last - first;
    const auto at = [&](std::int64_t i) { return first + static_cast<Index>(((i % n) + n) % n); };
    Index start = n;  // a corner that begins a run
    bool repeats = false;
    for (Index i = 0; i < n; ++i) {
      const Index o = origin(first + i), previous = origin(at(std::int64_t(i) - 1));
      if (o == kNoIndex)
        return;  // a face hole filling added: none
      if (o == previous)
        repeats = true;
      else if (start == n)
        start = i;
    }
    if (!repeats || start == n)
      return;
    std::vector<std::pair<Index, Index>> runs;  // (first corner, length)
    for (Index i = 0; i < n;) {
      Index length = 1;
      while (length < n && origin(at(start + i + length)) == origin(at(start + i)))
        ++length;
      runs.emplace_back(at(start + i), length);
      i += length;
    }
    const std::size_t m = runs.size();
    if (m < 3)
      return;
    std::size_t ascents = 0;
    for (std::size_t r = 0; r < m; ++r)
      ascents += origin(runs[(r + 1) % m].first) > origin(runs[r].first);
    const bool forward = ascents == m - 1, reversed = ascents == 1;
    if (forward == reversed)
      return;
    for (const auto& [run, length] : runs) {
      if (length < 2)
        continue;
      const std::int64_t r = run - first;
      const Index real = reversed ? at(r + length - 1) : run;
      const Index other = reversed ? at(r - 1) : at(r + length);
      for (Index k = 0; k + 1 < length; ++k) {
        const Index inserted = reversed ? at(r + k) : at(r + 1 + k);
        const double t = parameter_along(position(inserted), position(real), position(other));
        if (!out_.corner_texture.empty())
          out_.corner_texture[inserted] =
              between(0, out_.corner_texture[real], out_.corner_texture[other], t);
        if (!out_.corner_normal.empty())
          out_.corner_normal[inserted] =
              between(1, out_.corner_normal[real], out_.corner_normal[other], t);
      }
    }
  }

  const Point& position(Index corner) const {
    return mesh_.soup.positions[mesh_.soup.corner_vertices[corner]];
  }

  // The record (0: vt, 1: vn) at `t` between records a and b: a new one, made once per (a, b, t);
  // none if a or b is none. A normal keeps the length of its ends (unit normals stay unit).
  Index between(int slot, Index a, Index b, double t) {
    if (a == kNoIndex || b == kNoIndex)
      return kNoIndex;
    if (a == b || t == 0)
      return a;
    if (t == 1)
      return b;
    std::uint64_t bits = 0;
    std::memcpy(&bits, &t, sizeof bits);
    const auto key = std::make_tuple(slot, a, b, bits);
    const auto known = made_.find(key);
    if (known != made_.end())
      return known->second;
    std::vector<Record>& records = slot == 0 ? out_.texture_coordinates : out_.normals;
    const Record x = records[a], y = records[b];
    Record value;
    for (int i = 0; i < 3; ++i)
      value[i] = (1 - t) * x[i] + t * y[i];
    if (slot == 1) {
      const auto norm = [](const Record& v) {
        return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      };
      const double length = norm(value), wanted = (1 - t) * norm(x) + t * norm(y);
      if (length > 0) {
        for (double& v : value)
          v *= wanted / length;
      }
    }
    records.push_back(value);
    const Index made = static_cast<Index>(records.size() - 1);
    made_.emplace(key, made);
    return made;
  }

  const CornerAttributes& input_;
  const IndexedMesh& mesh_;
  CornerAttributes& out_;
  std::map<std::tuple<int, Index, Index, std::uint64_t>, Index> made_;
};

}  // namespace

CornerAttributes carry_corner_attributes(const CornerAttributes& input, const IndexedMesh& mesh) {
  CornerAttributes out;
  out.texture_coordinates = input.texture_coordinates;
  out.normals = input.normals;
  out.texture_components = input.texture_components;
  if (!input.corner_texture.empty() || !input.corner_normal.empty())
    CornerCarrier(input, mesh, out).carry();
  return out;
}

}  // namespace meshbridge::detail
