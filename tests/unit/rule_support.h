// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared by the *_rule tests: small models written as OFF text in the test, and the outcome
// of a repair seen per input face (component and the component's signed volume).

#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include "test_support.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace meshbridge::rule_test {

//! An OFF model as text ("OFF", counts, vertices, faces; any whitespace).
inline Soup from_off(const std::string& text) {
  std::istringstream in(text);
  std::string magic;
  std::size_t num_vertices = 0, num_faces = 0, num_edges = 0;
  in >> magic >> num_vertices >> num_faces >> num_edges;
  Soup soup;
  for (std::size_t v = 0; v < num_vertices; ++v) {
    double x, y, z;
    in >> x >> y >> z;
    soup.add_vertex({x, y, z});
  }
  for (std::size_t f = 0; f < num_faces; ++f) {
    std::size_t k = 0;
    in >> k;
    std::vector<Index> polygon(k);
    for (Index& v : polygon)
      in >> v;
    soup.add_polygon(polygon);
  }
  return soup;
}

//! Appends the six quads of an axis-aligned cube [lo, lo + size]^3, outward or inward.
inline void add_cube(Soup& soup, double lo, double size, bool outward) {
  const Index base = static_cast<Index>(soup.num_vertices());
  for (int i = 0; i < 8; ++i)
    soup.add_vertex({lo + size * (i & 1), lo + size * ((i >> 1) & 1), lo + size * ((i >> 2) & 1)});
  const Index quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    std::vector<Index> polygon{base + q[0], base + q[1], base + q[2], base + q[3]};
    if (!outward)
      std::reverse(polygon.begin(), polygon.end());
    soup.add_polygon(polygon);
  }
}

//! The soup with polygon f reversed.
inline Soup with_face_reversed(const Soup& soup, std::size_t reversed) {
  Soup out;
  out.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    std::vector<Index> polygon(p.begin(), p.end());
    if (f == reversed)
      std::reverse(polygon.begin(), polygon.end());
    out.add_polygon(polygon);
  }
  return out;
}

//! A repair's outcome per *input* face: its component (numbered by the smallest input face in
//! it) and that component's signed volume.
struct Outcome {
  RepairResult result;
  std::vector<Index> component;  //!< per input face
  std::vector<double> volume;    //!< per input face: its component's signed volume
};

inline Outcome repair_and_label(const Soup& soup, const RepairOptions& options = {}) {
  Outcome outcome;
  outcome.result = repair(soup, options);
  const Soup& out = outcome.result.mesh.soup;
  const std::vector<Index> label = test_support::face_components(out);
  const auto& origin = outcome.result.mesh.face_origin;
  std::map<Index, Index> smallest;  // output label -> smallest input face
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    auto it = smallest.find(label[f]);
    if (it == smallest.end() || origin[f] < it->second)
      smallest[label[f]] = origin[f];
  }
  outcome.component.assign(soup.num_faces(), kNoIndex);
  outcome.volume.assign(soup.num_faces(), 0.0);
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    outcome.component[origin[f]] = smallest[label[f]];
    outcome.volume[origin[f]] = test_support::signed_volume(out, label, label[f]);
  }
  return outcome;
}

//! The same model with faces shuffled and polygon starts rotated, keeping track of where each
//! face went: `order[i]` is the original face now at position i.
struct Shuffled {
  Soup soup;
  std::vector<Index> order;
};

inline Shuffled shuffled_with_order(const Soup& soup, std::uint32_t seed) {
  std::mt19937 random(seed);
  Shuffled s;
  s.order.resize(soup.num_faces());
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    s.order[f] = static_cast<Index>(f);
  std::shuffle(s.order.begin(), s.order.end(), random);
  s.soup.positions = soup.positions;
  for (Index f : s.order) {
    const PolygonView p = soup.polygon(f);
    const std::size_t shift = random() % p.size();
    std::vector<Index> polygon;
    for (std::size_t i = 0; i < p.size(); ++i)
      polygon.push_back(p[(i + shift) % p.size()]);
    s.soup.add_polygon(polygon);
  }
  return s;
}

//! Runs `check(soup, to_original)` on the model and on `shuffles` seeded shuffles of it;
//! `to_original[i]` is the original index of face i of the soup checked.
template <class Check>
void for_face_orders(const Soup& soup, std::uint32_t shuffles, Check check) {
  std::vector<Index> identity(soup.num_faces());
  for (std::size_t f = 0; f < identity.size(); ++f)
    identity[f] = static_cast<Index>(f);
  check(soup, identity);
  for (std::uint32_t seed = 1; seed <= shuffles && !::testing::Test::HasFailure(); ++seed) {
    SCOPED_TRACE("shuffle seed " + std::to_string(seed));
    const Shuffled s = shuffled_with_order(soup, seed);
    check(s.soup, s.order);
  }
}

}  // namespace meshbridge::rule_test
