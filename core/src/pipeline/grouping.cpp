// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/grouping.h"

namespace meshbridge::detail {

GroupedSides group_sides(const Soup& soup) {
  GroupedSides grouped;
  grouped.corner_face = corner_faces(soup);
  grouped.bridges = meshbridge::group_sides(soup, grouped.corner_face);
  return grouped;
}

Point newell_normal(const Soup& soup, std::size_t f) {
  const PolygonView polygon = soup.polygon(f);
  Point n(0, 0, 0);
  const std::size_t k = polygon.size();
  for (std::size_t i = 0; i < k; ++i) {
    const Point& p = soup.positions[polygon[i]];
    const Point& q = soup.positions[polygon[(i + 1) % k]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

}  // namespace meshbridge::detail
