// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Detection on an already grouped working soup, shared by detect_defects() and repair().

#include "meshbridge/defect_report.h"
#include "meshbridge/edge_bridges.h"

#include "working_soup.h"

#include <vector>

namespace meshbridge::detail {

//! Polygons of `soup` whose vertex set an earlier polygon has (all but the first of each set).
std::vector<Index> duplicate_polygons(const Soup& soup);

DefectReport detect(const WorkingSoup& working, const std::vector<Index>& corner_face,
                    const EdgeBridges& bridges);

}  // namespace meshbridge::detail
