// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/orientation.h"

#include "geometry/newell_normal.h"
#include "geometry/signed_volume.h"
#include "pipeline/nesting.h"
#include "pipeline/side_pairing.h"
#include "pipeline/singular_conflicts.h"

#include "union_find.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace meshbridge::detail {

namespace {

// Rounding-error scales are multiplied by this before a value is trusted over them: a few
// thousand times the double precision epsilon, so far above any real accumulated error.
constexpr double kRoundingMargin = 1e-12;

// The state of orient_components(), after CGAL's Polygon_soup_orienter: the paired faces'
// components, their volumes, and the decision per component, built in named steps.
class ComponentOrienter {
 public:
  ComponentOrienter(const Soup& soup, const CornerFaces& corner_face,
                    const std::vector<Index>& mate, const std::vector<char>& midpoint,
                    std::vector<char>& flipped)
      : soup_(soup),
        corner_face_(corner_face),
        mate_(mate),
        midpoint_(midpoint),
        flipped_(flipped) {}

  // Reverses whole components in `flipped`; returns the ambiguous nested shells.
  std::size_t run(AmbiguousNesting nested) {
    number_components();
    measure_volumes();
    classify_components();
    reverse_.assign(num_components_, 0);
    std::size_t ambiguous = 0;
    if (num_shells_ > 0)
      ambiguous = orient_shells(nested);
    if (num_undecided_ > 0)
      orient_undecided();
    for (Index f = 0; f < soup_.num_faces(); ++f)
      flipped_[f] ^= reverse_[component_[f]];
    return ambiguous;
  }

 private:
  // Components numbered by their smallest face (the root), in increasing order; everything
  // below is kept per component, not per face.
  void number_components() {
    UnionFind components(soup_.num_faces());
    for (Index c = 0; c < mate_.size(); ++c) {
      if (mate_[c] != kNoIndex)
        components.unite(corner_face_[c], corner_face_[mate_[c]]);
    }
    component_ = std::move(components).take_labels([&](Index root) {
      root_face_.push_back(root);
      return static_cast<Index>(root_face_.size() - 1);
    });
    num_components_ = root_face_.size();
  }

  // Six times the signed volume, as the faces will run, about a corner of the component (its
  // root face's first corner, which reversal keeps in place); the sum of its terms' magnitudes;
  // and a bound on its rounding error (the sum of |a| |b| |c| over the terms a . (b x c)).
  void measure_volumes() {
    open_.assign(num_components_, 0);
    volume_.assign(num_components_, 0.0);
    magnitude_.assign(num_components_, 0.0);
    noise_.assign(num_components_, 0.0);
    reference_.resize(num_components_);
    for (Index k = 0; k < num_components_; ++k)
      reference_[k] = soup_.positions[soup_.corner_vertices[soup_.face_begin[root_face_[k]]]];
    for (Index f = 0; f < soup_.num_faces(); ++f) {
      const Index k = component_[f];
      const PolygonView polygon = soup_.polygon(f);
      double v = 0;
      add_fan_volume(soup_, polygon, reference_[k], v, magnitude_[k], &noise_[k]);
      volume_[k] += flipped_[f] ? -v : v;
      for (Index c = soup_.face_begin[f]; c < soup_.face_begin[f + 1]; ++c) {
        if (mate_[c] == kNoIndex)
          open_[k] = 1;
      }
    }
  }

  // Closed shells with a volume, numbered; the others (open or flat) are undecided, judged on
  // their own evidence by orient_undecided().
  void classify_components() {
    shell_.assign(num_components_, kNoIndex);
    undecided_.assign(num_components_, kNoIndex);
    for (Index k = 0; k < num_components_; ++k) {
      const bool flat =
          std::abs(volume_[k]) <= std::max(1e-9 * magnitude_[k], kRoundingMargin * noise_[k]);
      if (open_[k] || flat) {
        undecided_[k] = static_cast<Index>(num_undecided_++);
      } else {
        shell_[k] = static_cast<Index>(num_shells_++);
      }
    }
  }

  // A shell's own winding is its intent when it is consistent as written (every face of it
  // reversed alike, or none): then only its sense relative to its container's counts, so a
  // global flip of the input changes nothing. Outermost shells face outward. Returns the
  // ambiguous nested shells.
  std::size_t orient_shells(AmbiguousNesting nested) {
    std::size_t ambiguous = 0;
    const std::size_t num_faces = soup_.num_faces();
    std::vector<char> written(num_components_, 2), mixed(num_components_, 0);
    for (Index f = 0; f < num_faces; ++f) {
      const Index k = component_[f];
      if (written[k] == 2)
        written[k] = flipped_[f];
      else if (written[k] != flipped_[f])
        mixed[k] = 1;
    }
    std::vector<Index> component_of(num_shells_);
    for (Index k = 0; k < num_components_; ++k) {
      if (shell_[k] != kNoIndex)
        component_of[shell_[k]] = k;
    }
    // Outward as written: positive volume once the reversals orientation made are undone.
    const auto written_outward = [&](Index k) { return (volume_[k] > 0) != (written[k] == 1); };
    Nesting nesting;
    if (num_shells_ > 1) {
      std::vector<Index> face_shell(num_faces);
      for (Index f = 0; f < num_faces; ++f)
        face_shell[f] = shell_[component_[f]];
      nesting = shell_nesting(soup_, flipped_, face_shell, num_shells_);
    } else {
      nesting.depth.assign(1, 0);
      nesting.parent.assign(1, kNoIndex);
    }
    // Each shell after its container: up the parent chain to a decided shell (or the
    // outermost), then down again. Degenerate inputs can nest without order (shells of no
    // thickness on each other's faces); a chain that comes back to a shell on it stops there.
    std::vector<char> outward(num_shells_, 1), state(num_shells_, 0);  // 0 new, 1 on chain, 2 done
    std::vector<Index> chain;
    for (Index start = 0; start < num_shells_; ++start) {
      chain.clear();
      for (Index s = start; s != kNoIndex && state[s] == 0; s = nesting.parent[s]) {
        state[s] = 1;
        chain.push_back(s);
      }
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const Index s = *it, p = nesting.parent[s];
        state[s] = 2;
        if (p == kNoIndex || state[p] != 2)
          continue;  // outermost (or a cycle's first shell): outward
        const Index k = component_of[s], q = component_of[p];
        // Even-odd: a cavity runs against its container.
        outward[s] = !outward[p];
        if (!mixed[k] && !mixed[q] && written_outward(k) == written_outward(q)) {
          // Written like its container (an insert, or a cavity wound the wrong way): ambiguous.
          ++ambiguous;
          if (nested == AmbiguousNesting::material)
            outward[s] = outward[p];
        }
      }
    }
    for (Index s = 0; s < num_shells_; ++s) {
      const Index k = component_of[s];
      reverse_[k] = (volume_[k] > 0) != (outward[s] != 0);
    }
    return ambiguous;
  }

  // Whether to reverse each open (or volume-less) component, on the best evidence it has:
  // - its volume, taken about its corners' centroid c (an open surface's volume depends on
  //   that point; the output's corners, with the midpoints of split pairs), when |volume|
  //   exceeds what capping its holes could change: |N| * R, with N
  //   the sum of its faces' vector areas (the holes' vector area, both times 2) and R the
  //   farthest boundary vertex from c; a slit such as a T-junction crack has no area, so it
  //   never hides a volume;
  // - otherwise its faces' windings as given, weighted by area: reversed if more area would
  //   end up reversed than not; on a tie, if more faces would (then: kept).
  void orient_undecided() {
    const std::size_t count = num_undecided_;
    std::vector<Point> area(count, Point(0, 0, 0)), centroid(count, Point(0, 0, 0));
    std::vector<double> corners(count, 0.0), winding(count, 0.0), reach(count, 0.0);
    std::vector<double> total_area(count, 0.0), reversed_faces(count, 0.0), faces(count, 0.0);
    std::vector<double> area_noise(count, 0.0);
    for (Index f = 0; f < soup_.num_faces(); ++f) {
      const Index u = undecided_[component_[f]];
      if (u == kNoIndex)
        continue;
      const Point n = newell_normal(soup_, f);
      area[u] += flipped_[f] ? -n : n;
      area_noise[u] += newell_rounding_scale(soup_, f);
      winding[u] += flipped_[f] ? -n.norm() : n.norm();
      total_area[u] += n.norm();
      reversed_faces[u] += flipped_[f];
      faces[u] += 1;
      for (Index v : soup_.polygon(f))
        centroid[u] += soup_.positions[v];
      corners[u] += static_cast<double>(soup_.polygon(f).size());
      if (midpoint_.empty())
        continue;
      // The corners the output will have: a pair split at its midpoint gives both its faces one
      // more there (emit_mesh()), so that repairing the output again judges the same centroid.
      for (Index c = soup_.face_begin[f]; c < soup_.face_begin[f + 1]; ++c) {
        if (!midpoint_[c])
          continue;
        const Point& a = soup_.positions[soup_.corner_vertices[c]];
        const Point& b = soup_.positions[soup_.corner_vertices[soup_.next_corner(c, f)]];
        centroid[u] += (a + b) * 0.5;
        corners[u] += 1;
      }
    }
    for (std::size_t u = 0; u < count; ++u)
      centroid[u] /= corners[u];
    for (Index c = 0; c < mate_.size(); ++c) {
      if (mate_[c] != kNoIndex)
        continue;
      const Index u = undecided_[component_[corner_face_[c]]];
      reach[u] =
          std::max(reach[u], (soup_.positions[soup_.corner_vertices[c]] - centroid[u]).norm());
    }
    for (Index k = 0; k < num_components_; ++k) {
      const Index u = undecided_[k];
      if (u == kNoIndex)
        continue;
      // The volume about the centroid, and a bound on its rounding error far above the real
      // one, so that a volume that is rounding noise (a flat or zero-area component) never
      // decides: the decision must come out the same when the output is repaired again.
      const Point offset = centroid[u] - reference_[k];
      const double about_centroid = volume_[k] - OpenMesh::dot(offset, area[u]);
      const double rounding = kRoundingMargin * (noise_[k] + offset.norm() * area_noise[u]);
      const bool volume_decides = std::abs(about_centroid) > area[u].norm() * reach[u] &&
                                  std::abs(about_centroid) > rounding;
      if (volume_decides) {
        reverse_[k] = about_centroid < 0;
      } else if (std::abs(winding[u]) > 1e-9 * total_area[u]) {
        reverse_[k] = winding[u] < 0;
      } else {  // areas tie (a face and its copy back to back): fewer faces reversed
        reverse_[k] = 2 * reversed_faces[u] > faces[u];
      }
    }
  }

  const Soup& soup_;
  const CornerFaces& corner_face_;
  const std::vector<Index>& mate_;
  const std::vector<char>& midpoint_;  // per side, or empty: pairs split at their midpoint
  std::vector<char>& flipped_;
  std::vector<Index> root_face_, component_;  // per component; per face
  std::size_t num_components_ = 0, num_shells_ = 0, num_undecided_ = 0;
  std::vector<char> open_, reverse_;
  std::vector<double> volume_, magnitude_, noise_;
  std::vector<Point> reference_;
  std::vector<Index> shell_, undecided_;  // per component: its number among shells / undecided
};

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

OrientationCounts orient_consistently(const Soup& soup, const CornerFaces& corner_face,
                                      bool cut_nonorientable, std::vector<Index>& mate,
                                      std::vector<char>& flipped, const EdgeBridges* bridges) {
  OrientationCounts counts;
  const std::size_t num_faces = soup.num_faces();
  flipped.assign(num_faces, 0);
  if (!has_inconsistent_pair(soup, mate))
    return counts;  // nothing to flip, nothing to cut
  std::vector<char> visited(num_faces, 0);
  std::vector<Index> queue, faces;
  queue.reserve(num_faces);
  std::vector<Index> edge_of_side;        // made when first needed
  std::optional<ParityUnionFind> blocks;  // likewise
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
    if (!cut_nonorientable && bridges != nullptr) {
      // Orientable through the input's own two-sided edges: the singular pairs yield.
      if (edge_of_side.empty()) {
        edge_of_side = edge_of_sides(soup, *bridges);
        blocks.emplace(num_faces);
      }
      faces.assign(queue.begin() + component_begin, queue.end());
      const Index cut = yield_singular_pairs(soup, corner_face, *bridges, edge_of_side, faces,
                                             *blocks, mate, flipped);
      if (cut != kNoIndex) {
        counts.sides_cut += cut;
        continue;
      }
    }
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

std::size_t orient_components(const Soup& soup, const GroupedSides& grouped, SidePairing& pairing,
                              AmbiguousNesting nested) {
  ComponentOrienter orienter(soup, grouped.corner_face, pairing.mate, pairing.midpoint,
                             pairing.flipped);
  return orienter.run(nested);
}

}  // namespace meshbridge::detail
