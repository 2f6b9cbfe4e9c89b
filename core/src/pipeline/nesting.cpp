// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/nesting.h"

#include "parallel_parts.h"
#include "pipeline/ray_crossings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

namespace meshbridge::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDecided = 0.1;   // |w - round(w)| below this decides inside / outside
constexpr std::size_t kTries = 8;  // sample points of a shell
constexpr std::size_t kMaxCells = std::size_t{1} << 21;
// Shells of at least this many faces answer inside tests by ray crossings.
constexpr std::size_t kRayFaces = 256;

struct Box {
  Point min{1e300, 1e300, 1e300};
  Point max{-1e300, -1e300, -1e300};
  void add(const Point& p) {
    for (int i = 0; i < 3; ++i) {
      min[i] = std::min(min[i], p[i]);
      max[i] = std::max(max[i], p[i]);
    }
  }
  bool contains(const Box& b) const {
    for (int i = 0; i < 3; ++i)
      if (b.min[i] < min[i] || b.max[i] > max[i])
        return false;
    return true;
  }
};

// Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom and Strackee);
// NaN if the origin lies on the triangle (in its plane, within rounding, and not outside it),
// where the angle jumps by 4 pi and its sign is noise. Written so that swapping b and c gives
// exactly the negated value (the numerator is antisymmetric, the denominator's roundings are
// symmetric).
double solid_angle(const Point& a, const Point& b, const Point& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = OpenMesh::dot(a, OpenMesh::cross(b, c));
  const double lbc = lb * lc;
  const double denominator =
      la * lbc + OpenMesh::dot(b, c) * la + (OpenMesh::dot(a, b) * lc + OpenMesh::dot(a, c) * lb);
  if (std::abs(numerator) <= 1e-9 * la * lbc && denominator <= 0)
    return std::numeric_limits<double>::quiet_NaN();
  return 2 * std::atan2(numerator, denominator);
}

bool position_less(const Point& p, const Point& q) {
  return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
}

// Whether to walk polygon f from its first corner backwards: chosen by positions alone, so that
// the polygon and its reversal (same first corner, see emit.cpp) are walked through the same
// positions in the same order. A sum taken along that walk then comes out bit for bit the same
// (or exactly negated) after the repair reversed the face or renumbered its vertices, and so do
// the decisions made on it: repairing the output again decides the same.
bool walk_backwards(const Soup& soup, PolygonView polygon) {
  const std::size_t k = polygon.size();
  for (std::size_t i = 1; i < k; ++i) {
    const Point& forward = soup.positions[polygon[i]];
    const Point& backward = soup.positions[polygon[k - i]];
    if (position_less(forward, backward))
      return false;
    if (position_less(backward, forward))
      return true;
  }
  return false;
}

// Corner i of polygon along the walk (i = 0 is the first corner either way).
Index walked(PolygonView polygon, bool backwards, std::size_t i) {
  return polygon[backwards && i > 0 ? polygon.size() - i : i];
}

Point centroid(const Soup& soup, Index f) {
  Point sum(0, 0, 0);
  const PolygonView polygon = soup.polygon(f);
  const bool backwards = walk_backwards(soup, polygon);
  for (std::size_t i = 0; i < polygon.size(); ++i)
    sum += soup.positions[walked(polygon, backwards, i)];
  return sum / static_cast<double>(polygon.size());
}

// A uniform grid over boxes, about one cell per box (at most kMaxCells, 1024 a side); each box
// is listed in every cell it touches.
class BoxGrid {
 public:
  explicit BoxGrid(const std::vector<Box>& boxes) {
    for (const Box& b : boxes) {
      all_.add(b.min);
      all_.add(b.max);
    }
    extent_ = all_.max - all_.min;
    const double largest = std::max({extent_[0], extent_[1], extent_[2]});
    if (largest > 0) {
      double volume = 1;
      for (int i = 0; i < 3; ++i)
        volume *= std::max(extent_[i], largest * 1e-3);
      const double size =
          std::cbrt(volume / static_cast<double>(std::min(boxes.size(), kMaxCells)));
      for (int i = 0; i < 3; ++i)
        cells_[i] = std::clamp<std::size_t>(static_cast<std::size_t>(extent_[i] / size), 1, 1024);
    }
    const std::size_t num_cells = cells_[0] * cells_[1] * cells_[2];
    begin_.assign(num_cells + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<Index> fill;
      if (pass == 1) {
        for (std::size_t c = 0; c < num_cells; ++c)
          begin_[c + 1] += begin_[c];
        listed_.resize(begin_.back());
        fill.assign(begin_.begin(), begin_.end() - 1);
      }
      for (Index s = 0; s < boxes.size(); ++s) {
        const Box& b = boxes[s];
        for (std::size_t z = cell(b.min, 2); z <= cell(b.max, 2); ++z)
          for (std::size_t y = cell(b.min, 1); y <= cell(b.max, 1); ++y)
            for (std::size_t x = cell(b.min, 0); x <= cell(b.max, 0); ++x) {
              const std::size_t c = (z * cells_[1] + y) * cells_[0] + x;
              if (pass == 0)
                ++begin_[c + 1];
              else
                listed_[fill[c]++] = s;
            }
      }
    }
  }
  //! The boxes listed in the cell of point p: [first, last).
  std::pair<const Index*, const Index*> at(const Point& p) const {
    const std::size_t c = (cell(p, 2) * cells_[1] + cell(p, 1)) * cells_[0] + cell(p, 0);
    return {listed_.data() + begin_[c], listed_.data() + begin_[c + 1]};
  }

 private:
  std::size_t cell(const Point& p, int axis) const {
    if (!(extent_[axis] > 0))
      return 0;
    const double t = (p[axis] - all_.min[axis]) / extent_[axis] * static_cast<double>(cells_[axis]);
    return std::min(cells_[axis] - 1, static_cast<std::size_t>(std::max(0.0, t)));
  }
  Box all_;
  Point extent_{0, 0, 0};
  std::array<std::size_t, 3> cells_{1, 1, 1};
  std::vector<Index> begin_;
  std::vector<Index> listed_;
};

}  // namespace

double winding_number(const Soup& soup, const std::vector<char>& flipped, const Index* faces_begin,
                      const Index* faces_end, const Point& p) {
  double total = 0;
  for (const Index* f = faces_begin; f != faces_end; ++f) {
    const PolygonView polygon = soup.polygon(*f);
    const bool backwards = walk_backwards(soup, polygon);
    const Point a = soup.positions[polygon[0]] - p;
    double angle = 0;
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      angle += solid_angle(a, soup.positions[walked(polygon, backwards, i)] - p,
                           soup.positions[walked(polygon, backwards, i + 1)] - p);
    }
    total += backwards != (flipped[*f] != 0) ? -angle : angle;
  }
  return total / (4 * kPi);
}

std::vector<Index> nesting_depths(const Soup& soup, const std::vector<char>& flipped,
                                  const std::vector<Index>& face_shell, std::size_t num_shells) {
  return shell_nesting(soup, flipped, face_shell, num_shells).depth;
}

Nesting shell_nesting(const Soup& soup, const std::vector<char>& flipped,
                      const std::vector<Index>& face_shell, std::size_t num_shells) {
  Nesting nesting;
  nesting.depth.assign(num_shells, 0);
  nesting.parent.assign(num_shells, kNoIndex);
  if (num_shells < 2)
    return nesting;
  std::vector<Index>& depth = nesting.depth;
  // The shells that contain each shell (few: its nesting depth).
  std::vector<std::vector<Index>> containers(num_shells);
  // Faces of each shell (CSR) and the shells' boxes.
  std::vector<Index> shell_begin(num_shells + 1, 0);
  for (Index s : face_shell)
    if (s != kNoIndex)
      ++shell_begin[s + 1];
  for (std::size_t s = 0; s < num_shells; ++s)
    shell_begin[s + 1] += shell_begin[s];
  std::vector<Index> shell_faces(shell_begin.back());
  std::vector<Box> box(num_shells);
  {
    std::vector<Index> fill(shell_begin.begin(), shell_begin.end() - 1);
    for (Index f = 0; f < face_shell.size(); ++f) {
      const Index s = face_shell[f];
      if (s == kNoIndex)
        continue;
      shell_faces[fill[s]++] = f;
      for (Index v : soup.polygon(f))
        box[s].add(soup.positions[v]);
    }
  }
  // Only shells listed in the grid cell of S's box centre can contain S. Each shell's depth is
  // its own: with several threads, each takes a share of the shells.
  const BoxGrid grid(box);
  // A shell of many faces that may contain others answers by ray crossings (RayCrossings):
  // the solid-angle sum would cost all its faces for every point of every shell inside its box.
  std::vector<std::unique_ptr<RayCrossings>> rays(num_shells);
  {
    std::vector<char> container(num_shells, 0);
    for (Index s = 0; s < num_shells; ++s) {
      const auto [first, last] = grid.at((box[s].min + box[s].max) * 0.5);
      for (const Index* it = first; it != last; ++it) {
        if (*it != s && box[*it].contains(box[s]))
          container[*it] = 1;
      }
    }
    for (Index t = 0; t < num_shells; ++t) {
      if (container[t] && shell_begin[t + 1] - shell_begin[t] >= kRayFaces) {
        rays[t] = std::make_unique<RayCrossings>(soup, flipped, shell_faces.data() + shell_begin[t],
                                                 shell_faces.data() + shell_begin[t + 1]);
      }
    }
  }
  constexpr std::size_t kLeastShellsPerThread = 2048;
  const unsigned parts = static_cast<unsigned>(std::clamp<std::size_t>(
      num_shells / kLeastShellsPerThread, 1, std::max(worker_threads(), 1u)));
  run_parts(parts, [&](unsigned part) {
    const Index end = static_cast<Index>(part_begin(num_shells, parts, part + 1));
    for (Index s = static_cast<Index>(part_begin(num_shells, parts, part)); s < end; ++s) {
      const auto [first, last] = grid.at((box[s].min + box[s].max) * 0.5);
      for (const Index* it = first; it != last; ++it) {
        const Index t = *it;
        if (t == s || !box[t].contains(box[s]))
          continue;
        const Index* t_first = shell_faces.data() + shell_begin[t];
        const Index* t_last = shell_faces.data() + shell_begin[t + 1];
        // Up to kTries points spread over S: inside only if every decided one is.
        const std::size_t n = shell_begin[s + 1] - shell_begin[s];
        const std::size_t tries = std::min(kTries, n);
        bool inside = false;
        for (std::size_t k = 0; k < tries; ++k) {
          const Index f = shell_faces[shell_begin[s] + k * n / tries];
          const Point point = centroid(soup, f);
          const double w =
              std::abs(rays[t] != nullptr ? rays[t]->at(point)
                                          : winding_number(soup, flipped, t_first, t_last, point));
          if (std::isnan(w))
            continue;  // the point lies on T: undecided
          if (w > 1 - kDecided && std::abs(w - std::round(w)) < kDecided) {
            inside = true;
          } else {
            inside = false;  // outside, or crossing T: not nested
            break;
          }
        }
        if (inside)
          containers[s].push_back(t);
      }
      depth[s] = static_cast<Index>(containers[s].size());
    }
  });
  for (Index s = 0; s < num_shells; ++s) {
    for (Index t : containers[s]) {
      if (nesting.parent[s] == kNoIndex || depth[t] > depth[nesting.parent[s]])
        nesting.parent[s] = t;
    }
  }
  return nesting;
}

}  // namespace meshbridge::detail
