// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/orientation.h"

#include "union_find.h"

#include <cmath>

namespace meshbridge::detail {

namespace {

// Two paired sides run the same way iff they start at the same vertex.
bool same_way(const Soup& soup, Index c, Index m) {
  return soup.corner_vertices[c] == soup.corner_vertices[m];
}

}  // namespace

bool has_inconsistent_pair(const Soup& soup, const std::vector<Index>& mate) {
  for (Index c = 0; c < mate.size(); ++c) {
    if (mate[c] != kNoIndex && same_way(soup, c, mate[c]))
      return true;
  }
  return false;
}

std::size_t cut_inconsistent_pairs(const Soup& soup, std::vector<Index>& mate) {
  std::size_t cut = 0;
  for (Index c = 0; c < mate.size(); ++c) {
    const Index m = mate[c];
    if (m != kNoIndex && same_way(soup, c, m)) {
      mate[c] = kNoIndex;
      mate[m] = kNoIndex;
      cut += 2;
    }
  }
  return cut;
}

OrientationCounts orient_consistently(const Soup& soup, const std::vector<Index>& corner_face,
                                      bool cut_nonorientable, std::vector<Index>& mate,
                                      std::vector<char>& flipped) {
  OrientationCounts counts;
  const std::size_t num_faces = soup.num_faces();
  flipped.assign(num_faces, 0);
  if (!has_inconsistent_pair(soup, mate))
    return counts;  // nothing to flip, nothing to cut
  std::vector<char> visited(num_faces, 0);
  std::vector<Index> queue;
  queue.reserve(num_faces);
  for (Index root = 0; root < num_faces; ++root) {
    if (visited[root])
      continue;
    const std::size_t component_begin = queue.size();
    bool conflict = false;
    visited[root] = 1;
    queue.push_back(root);
    for (std::size_t head = component_begin; head < queue.size(); ++head) {
      const Index f = queue[head];
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        const Index m = mate[c];
        if (m == kNoIndex)
          continue;
        const Index g = corner_face[m];
        const char wanted = static_cast<char>(flipped[f] ^ (same_way(soup, c, m) ? 1 : 0));
        if (!visited[g]) {
          visited[g] = 1;
          flipped[g] = wanted;
          queue.push_back(g);
        } else if (flipped[g] != wanted) {
          conflict = true;
          if (cut_nonorientable) {
            mate[c] = kNoIndex;
            mate[m] = kNoIndex;
            counts.sides_cut += 2;
          }
        }
      }
    }
    if (!conflict)
      continue;
    ++counts.nonorientable_components;
    if (cut_nonorientable)
      continue;
    for (std::size_t i = component_begin; i < queue.size(); ++i)
      flipped[queue[i]] = 0;
    for (std::size_t i = component_begin; i < queue.size(); ++i) {
      const Index f = queue[i];
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        const Index m = mate[c];
        if (m != kNoIndex && same_way(soup, c, m)) {
          mate[c] = kNoIndex;
          mate[m] = kNoIndex;
          counts.sides_cut += 2;
        }
      }
    }
  }
  return counts;
}

void orient_components(const Soup& soup, const GroupedSides& grouped, SidePairing& pairing) {
  const std::vector<Index>& corner_face = grouped.corner_face;
  const std::vector<Index>& mate = pairing.mate;
  std::vector<char>& flipped = pairing.flipped;
  const std::size_t num_faces = soup.num_faces();
  UnionFind components(num_faces);
  for (Index c = 0; c < mate.size(); ++c) {
    if (mate[c] != kNoIndex)
      components.unite(corner_face[c], corner_face[mate[c]]);
  }
  std::vector<char> open(num_faces, 0);
  std::vector<double> volume(num_faces, 0.0), magnitude(num_faces, 0.0);
  std::vector<Index> faces(num_faces, 0), reversed(num_faces, 0);
  for (Index f = 0; f < num_faces; ++f) {
    const Index r = components.find(f);
    ++faces[r];
    reversed[r] += flipped[f];
    const PolygonView polygon = soup.polygon(f);
    double v = 0;
    const Point& p0 = soup.positions[polygon[0]];
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const double term = OpenMesh::dot(
          p0, OpenMesh::cross(soup.positions[polygon[i]], soup.positions[polygon[i + 1]]));
      v += term;
      magnitude[r] += std::abs(term);
    }
    volume[r] += flipped[f] ? -v : v;
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      if (mate[c] == kNoIndex)
        open[r] = 1;
    }
  }
  std::vector<char> reverse(num_faces, 0);
  for (Index r = 0; r < num_faces; ++r) {
    if (faces[r] == 0)
      continue;
    const bool flat = std::abs(volume[r]) <= 1e-9 * magnitude[r];
    reverse[r] = (open[r] || flat) ? (2 * reversed[r] > faces[r]) : (volume[r] < 0);
  }
  for (Index f = 0; f < num_faces; ++f)
    flipped[f] ^= reverse[components.find(f)];
}

}  // namespace meshbridge::detail
