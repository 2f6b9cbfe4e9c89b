// SPDX-License-Identifier: GPL-3.0-or-later
// Every face record as kept, split or set aside: the same rule as repair's WorkingSoup.

#include "io/formats.h"

#include <algorithm>
#include <vector>

namespace meshbridge::detail {

void account_faces(const Soup& soup, ReadInfo& info) {
  std::vector<Index> loop;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    // Fast path: a triangle with three different corners (almost every face).
    if (polygon.size() == 3 && polygon[0] != polygon[1] && polygon[1] != polygon[2] &&
        polygon[0] != polygon[2]) {
      ++info.faces_kept;
      continue;
    }
    // Collapse consecutive repeats (cyclically), as WorkingSoup does.
    loop.clear();
    for (Index v : polygon) {
      if (loop.empty() || loop.back() != v)
        loop.push_back(v);
    }
    while (loop.size() > 1 && loop.front() == loop.back())
      loop.pop_back();
    std::vector<Index> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t distinct =
        static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    if (distinct < 3)
      ++info.faces_set_aside;
    else if (distinct < loop.size())
      ++info.faces_split;
    else
      ++info.faces_kept;
  }
  info.faces_set_aside += info.faces_without_corners;
}

}  // namespace meshbridge::detail
