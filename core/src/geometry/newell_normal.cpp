// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/newell_normal.h"

namespace meshbridge::detail {

Point newell_normal(const Soup& soup, std::size_t f) {
  return newell_normal(soup, soup.polygon(f));
}

Point newell_normal(const Soup& soup, PolygonView polygon) {
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

double newell_rounding_scale(const Soup& soup, Index f) {
  const PolygonView polygon = soup.polygon(f);
  double scale = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& p = soup.positions[polygon[i]];
    const Point& q = soup.positions[polygon[(i + 1) % polygon.size()]];
    scale += (p - q).norm() * (p + q).norm();
  }
  return scale;
}

}  // namespace meshbridge::detail
