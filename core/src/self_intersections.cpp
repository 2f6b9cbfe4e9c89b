// SPDX-License-Identifier: GPL-3.0-or-later
// find_self_intersections(): the soup cut into triangles on vertices merged by position, a
// uniform grid as the broad phase (each pair of overlapping boxes tested once, in the cell that
// holds the low corner of their common box), the narrow phase in triangle_pairs.cpp.
#include "meshbridge/self_intersections.h"

#include "meshbridge/validate.h"

#include "geometry/triangulate.h"
#include "parallel_parts.h"
#include "triangle_pairs.h"
#include "union_find.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace meshbridge {

namespace {

using detail::TriangleCorners;

//! Vertex -> the smallest vertex index at the same position (exact coordinates; -0 == +0), so
//! that repair's split copies share their corner.
std::vector<Index> ids_by_position(const Soup& soup) {
  const std::size_t n = soup.num_vertices();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index(0));
  const auto& p = soup.positions;
  std::sort(order.begin(), order.end(), [&](Index a, Index b) {
    for (int i = 0; i < 3; ++i)
      if (p[a][i] != p[b][i])
        return p[a][i] < p[b][i];
    return a < b;
  });
  std::vector<Index> id(n);
  for (std::size_t k = 0; k < n; ++k) {
    const bool same = k > 0 && p[order[k]] == p[order[k - 1]];
    id[order[k]] = same ? id[order[k - 1]] : order[k];
  }
  return id;
}

//! A triangle's bounding box in floats, rounded outward (half the memory of doubles; the
//! broad phase only needs boxes that contain the triangle).
struct Box {
  float lo[3], hi[3];
};

float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -HUGE_VALF) : f;
}
float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, HUGE_VALF) : f;
}

//! The soup's triangles (corners as position ids), the face of each and its bounding box.
struct Triangles {
  std::vector<TriangleCorners> corners;
  std::vector<Index> face;
  std::vector<Box> box;
  std::size_t degenerate = 0;
};

//! The triangles of faces [first, last).
Triangles cut_faces(const Soup& soup, const std::vector<Index>& id, std::size_t first,
                    std::size_t last) {
  Triangles out;
  out.corners.reserve(last - first);
  out.face.reserve(last - first);
  out.box.reserve(last - first);
  detail::Triangulation cut;
  const Point* positions = soup.positions.data();
  const auto keep = [&](TriangleCorners t, std::size_t f) {
    for (Index& v : t)
      v = id[v];
    if (detail::is_degenerate_triangle(positions, t)) {
      ++out.degenerate;
      return;
    }
    Box b;
    for (int i = 0; i < 3; ++i) {
      b.lo[i] = round_down(std::min({positions[t[0]][i], positions[t[1]][i], positions[t[2]][i]}));
      b.hi[i] = round_up(std::max({positions[t[0]][i], positions[t[1]][i], positions[t[2]][i]}));
    }
    out.corners.push_back(t);
    out.face.push_back(static_cast<Index>(f));
    out.box.push_back(b);
  };
  for (std::size_t f = first; f < last; ++f) {
    const PolygonView polygon = soup.polygon(f);
    if (polygon.size() == 3) {
      keep({polygon[0], polygon[1], polygon[2]}, f);
      continue;
    }
    detail::triangulate_polygon(soup, f, cut);
    for (const auto& t : cut.triangles)
      keep(t, f);
  }
  return out;
}

//! The soup's triangles in face order, the faces cut in `parts` parts side by side.
Triangles cut_into_triangles(const Soup& soup, const std::vector<Index>& id, unsigned parts) {
  const std::size_t faces = soup.num_faces();
  std::vector<Triangles> part(parts);
  detail::run_parts(parts, [&](unsigned k) {
    part[k] = cut_faces(soup, id, detail::part_begin(faces, parts, k),
                        detail::part_begin(faces, parts, k + 1));
  });
  if (parts == 1)
    return std::move(part[0]);
  Triangles out;
  std::size_t total = 0;
  for (const Triangles& p : part)
    total += p.box.size();
  out.corners.reserve(total);
  out.face.reserve(total);
  out.box.reserve(total);
  for (const Triangles& p : part) {
    out.corners.insert(out.corners.end(), p.corners.begin(), p.corners.end());
    out.face.insert(out.face.end(), p.face.begin(), p.face.end());
    out.box.insert(out.box.end(), p.box.begin(), p.box.end());
    out.degenerate += p.degenerate;
  }
  return out;
}

//! A uniform grid over the triangles' boxes: about `2 * triangles` cells (fewer along a flat
//! extent), coarser while the boxes would fill more than 16 cells per triangle on average.
class Grid {
 public:
  explicit Grid(const std::vector<Box>& boxes) {
    for (int i = 0; i < 3; ++i) {
      lo_[i] = HUGE_VAL;
      double hi = -HUGE_VAL;
      for (const Box& b : boxes) {
        lo_[i] = std::min<double>(lo_[i], b.lo[i]);
        hi = std::max<double>(hi, b.hi[i]);
      }
      extent_[i] = boxes.empty() ? 0 : hi - lo_[i];
    }
    const double target = 2.0 * std::max<std::size_t>(boxes.size(), 1);
    double low = 0, high = std::max({extent_[0], extent_[1], extent_[2]});
    if (!std::isfinite(high))
      high = 0;  // coordinates apart by more than a double holds: one cell (slow, but right)
    if (high > 0) {
      for (int step = 0; step < 64; ++step) {  // the smallest cell size within the target
        const double mid = 0.5 * (low + high);
        (mid > 0 && cells_for(mid) <= target ? high : low) = mid;
      }
    }
    for (;;) {
      set_size(high);
      if (high <= 0 || !too_many_entries(boxes))
        break;
      high *= 2;
    }
  }

  std::size_t num_cells() const { return cells_[0] * cells_[1] * cells_[2]; }
  //! Lists every box in every cell it overlaps (counting sort).
  void fill(const std::vector<Box>& boxes) {
    const std::size_t n = cells_[0] * cells_[1] * cells_[2];
    begin_.assign(n + 1, 0);
    for (const Box& b : boxes)
      for_cells(b, [&](std::size_t c) { ++begin_[c + 1]; });
    for (std::size_t c = 0; c < n; ++c)
      begin_[c + 1] += begin_[c];
    listed_.resize(begin_[n]);
    std::vector<Index> next(begin_.begin(), begin_.end() - 1);
    for (std::size_t t = 0; t < boxes.size(); ++t)
      for_cells(boxes[t], [&](std::size_t c) { listed_[next[c]++] = static_cast<Index>(t); });
  }
  const Index* cell_begin(std::size_t c) const { return listed_.data() + begin_[c]; }
  const Index* cell_end(std::size_t c) const { return listed_.data() + begin_[c + 1]; }
  //! The cell of a point.
  std::size_t cell_of(const float* p) const {
    return (index(p[2], 2) * cells_[1] + index(p[1], 1)) * cells_[0] + index(p[0], 0);
  }

 private:
  double cells_for(double size) const {
    double cells = 1;
    for (double e : extent_)
      cells *= std::max(1.0, std::ceil(e / size));
    return cells;
  }
  void set_size(double size) {
    size_ = size;
    for (int i = 0; i < 3; ++i)
      cells_[i] = size > 0 ? std::max<std::size_t>(1, std::ceil(extent_[i] / size)) : 1;
  }
  std::size_t index(double x, int axis) const {
    if (size_ <= 0)
      return 0;
    const double k = (x - lo_[axis]) / size_;  // monotone in x: a box's cells are a range
    return std::min(cells_[axis] - 1, static_cast<std::size_t>(std::max(0.0, k)));
  }
  template <class Visit>
  void for_cells(const Box& b, Visit&& visit) const {
    const std::size_t x0 = index(b.lo[0], 0), x1 = index(b.hi[0], 0);
    const std::size_t y0 = index(b.lo[1], 1), y1 = index(b.hi[1], 1);
    const std::size_t z0 = index(b.lo[2], 2), z1 = index(b.hi[2], 2);
    for (std::size_t z = z0; z <= z1; ++z)
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x)
          visit((z * cells_[1] + y) * cells_[0] + x);
  }
  //! True if the boxes would fill more than 16 cells per box on average.
  bool too_many_entries(const std::vector<Box>& boxes) const {
    // (and never more than 32-bit offsets hold)
    const std::size_t limit =
        std::min<std::size_t>(16 * std::max<std::size_t>(boxes.size(), 1), kNoIndex - 1);
    std::size_t entries = 0;
    for (const Box& b : boxes) {
      entries += (index(b.hi[0], 0) - index(b.lo[0], 0) + 1) *
                 (index(b.hi[1], 1) - index(b.lo[1], 1) + 1) *
                 (index(b.hi[2], 2) - index(b.lo[2], 2) + 1);
      if (entries > limit)
        return true;
    }
    return false;
  }

  double lo_[3] = {0, 0, 0}, extent_[3] = {0, 0, 0};
  double size_ = 0;
  std::size_t cells_[3] = {1, 1, 1};
  std::vector<Index> begin_{0, 0};  //!< cell -> first entry in listed_ (CSR), by fill()
  std::vector<Index> listed_;       //!< triangles of each cell
};

//! Puts the triangles in the order of the grid cell of their box's low corner, so that those
//! of one cell lie together in memory (the file's face order may be any), then lists them.
void order_by_cell(Triangles& triangles, Grid& grid, unsigned threads) {
  const std::size_t n = triangles.box.size();
  std::vector<Index> count(grid.num_cells() + 1, 0);
  std::vector<Index> cell(n);
  for (std::size_t t = 0; t < n; ++t) {
    cell[t] = static_cast<Index>(grid.cell_of(triangles.box[t].lo));
    ++count[cell[t] + 1];
  }
  for (std::size_t c = 0; c + 1 < count.size(); ++c)
    count[c + 1] += count[c];
  std::vector<Index> order(n);
  for (std::size_t t = 0; t < n; ++t)
    order[count[cell[t]]++] = static_cast<Index>(t);
  Triangles sorted;
  sorted.degenerate = triangles.degenerate;
  sorted.corners.resize(n);
  sorted.face.resize(n);
  sorted.box.resize(n);
  detail::run_parts(threads, [&](unsigned k) {
    const std::size_t last = detail::part_begin(n, threads, k + 1);
    for (std::size_t i = detail::part_begin(n, threads, k); i < last; ++i) {
      sorted.corners[i] = triangles.corners[order[i]];
      sorted.face[i] = triangles.face[order[i]];
      sorted.box[i] = triangles.box[order[i]];
    }
  });
  triangles = std::move(sorted);
  grid.fill(triangles.box);
}

bool boxes_overlap(const Box& a, const Box& b) {
  for (int i = 0; i < 3; ++i)
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i])
      return false;
  return true;
}

//! The intersecting face pairs (sorted, unique), the cells shared out among `threads`.
std::vector<FacePair> intersecting_pairs(const Soup& soup, const Triangles& triangles,
                                         const Grid& grid, unsigned threads) {
  const Point* positions = soup.positions.data();
  constexpr std::size_t kChunk = 1024;  // cells taken at a time
  std::atomic<std::size_t> next_chunk{0};
  std::vector<std::vector<FacePair>> found(threads);
  detail::run_parts(threads, [&](unsigned part) {
    std::vector<FacePair>& mine = found[part];
    std::vector<Index> in_cell;
    for (;;) {
      const std::size_t first = next_chunk.fetch_add(kChunk);
      if (first >= grid.num_cells())
        break;
      const std::size_t last = std::min(grid.num_cells(), first + kChunk);
      for (std::size_t c = first; c < last; ++c) {
        // The cell's boxes by their low x, swept: a box meets those starting before it ends.
        in_cell.assign(grid.cell_begin(c), grid.cell_end(c));
        if (in_cell.size() < 2)
          continue;
        std::sort(in_cell.begin(), in_cell.end(), [&](Index a, Index b) {
          return triangles.box[a].lo[0] < triangles.box[b].lo[0];
        });
        for (auto i = in_cell.begin(); i != in_cell.end(); ++i) {
          const Box& bi = triangles.box[*i];
          for (auto j = i + 1; j != in_cell.end(); ++j) {
            const Box& bj = triangles.box[*j];
            if (bj.lo[0] > bi.hi[0])
              break;
            if (!boxes_overlap(bi, bj) || triangles.face[*i] == triangles.face[*j])
              continue;
            const float low[3] = {std::max(bi.lo[0], bj.lo[0]), std::max(bi.lo[1], bj.lo[1]),
                                  std::max(bi.lo[2], bj.lo[2])};
            if (grid.cell_of(low) != c)
              continue;  // tested in another cell
            if (!detail::triangles_intersect(positions, triangles.corners[*i],
                                             triangles.corners[*j]))
              continue;
            const Index f = triangles.face[*i], g = triangles.face[*j];
            mine.push_back({std::min(f, g), std::max(f, g)});
          }
        }
      }
    }
  });
  std::vector<FacePair> pairs;
  for (const auto& part : found)
    pairs.insert(pairs.end(), part.begin(), part.end());
  const auto less = [](const FacePair& a, const FacePair& b) {
    return a.f0 != b.f0 ? a.f0 < b.f0 : a.f1 < b.f1;
  };
  std::sort(pairs.begin(), pairs.end(), less);
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

//! Component of every face (connected through shared vertex indices), numbered in order of
//! first face; returns their number.
std::size_t face_components(const Soup& soup, std::vector<Index>& component) {
  detail::UnionFind sets(soup.num_vertices());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    for (std::size_t i = 1; i < polygon.size(); ++i)
      sets.unite(polygon[0], polygon[i]);
  }
  std::vector<Index> label_of_root(soup.num_vertices(), kNoIndex);
  component.assign(soup.num_faces(), kNoIndex);
  Index count = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    Index& label = label_of_root[sets.find(soup.polygon(f)[0])];
    if (label == kNoIndex)
      label = count++;
    component[f] = label;
  }
  return count;
}

template <class T, class Print>
void list(std::ostringstream& out, const char* label, const std::vector<T>& items,
          std::size_t max_listed, Print print) {
  out << "  " << label << ": " << items.size();
  if (!items.empty() && max_listed > 0) {
    out << "  [";
    for (std::size_t i = 0; i < items.size() && i < max_listed; ++i) {
      out << (i ? " " : "");
      print(items[i]);
    }
    if (items.size() > max_listed)
      out << " ...";
    out << "]";
  }
  out << "\n";
}

}  // namespace

std::string to_text(const SelfIntersectionReport& r, std::size_t max_listed) {
  std::ostringstream out;
  const auto pair = [&](const FacePair& p) { out << p.f0 << "-" << p.f1; };
  list(out, "self-intersecting face pairs", r.face_pairs, max_listed, pair);
  list(out, "faces in them", r.faces, max_listed, [&](Index f) { out << f; });
  list(out, "pairs of components (shells) crossing", r.component_pairs, max_listed, pair);
  if (r.degenerate_triangles > 0)
    out << "  degenerate triangles not tested (zero area): " << r.degenerate_triangles << "\n";
  return out.str();
}

bool self_intersections_available() {
  return detail::triangle_predicates_available();
}

SelfIntersectionReport find_self_intersections(const Soup& soup,
                                               const SelfIntersectionOptions& options) {
  validate_soup(soup);
  if (!self_intersections_available()) {
    throw std::runtime_error(
        "find_self_intersections: this build of MeshBridge cannot find self-intersections (it "
        "was built without CGAL, whose exact predicates they need; Debian: libcgal-dev)");
  }
  SelfIntersectionReport report;
  // Threads for `items` elements: as asked, or by default one per 65,536 (small meshes on one
  // thread: starting threads would cost more than it saves), at most worker_threads().
  const auto share = [&options](std::size_t items) {
    if (options.threads > 0)
      return options.threads;
    return std::max(
        1u, std::min<unsigned>(detail::worker_threads(), static_cast<unsigned>(items / 65536 + 1)));
  };
  const std::vector<Index> id = ids_by_position(soup);
  Triangles triangles = cut_into_triangles(soup, id, share(soup.num_faces()));
  report.degenerate_triangles = triangles.degenerate;
  Grid grid(triangles.box);
  const unsigned threads = share(triangles.box.size());
  order_by_cell(triangles, grid, threads);
  report.face_pairs = intersecting_pairs(soup, triangles, grid, threads);

  for (const FacePair& p : report.face_pairs) {
    report.faces.push_back(p.f0);
    report.faces.push_back(p.f1);
  }
  std::sort(report.faces.begin(), report.faces.end());
  report.faces.erase(std::unique(report.faces.begin(), report.faces.end()), report.faces.end());

  std::vector<Index> component;
  report.num_components = face_components(soup, component);
  for (const FacePair& p : report.face_pairs) {
    const Index a = component[p.f0], b = component[p.f1];
    if (a != b)
      report.component_pairs.push_back({std::min(a, b), std::max(a, b)});
  }
  auto& cp = report.component_pairs;
  std::sort(cp.begin(), cp.end(), [](const FacePair& a, const FacePair& b) {
    return a.f0 != b.f0 ? a.f0 < b.f0 : a.f1 < b.f1;
  });
  cp.erase(std::unique(cp.begin(), cp.end()), cp.end());
  return report;
}

}  // namespace meshbridge
