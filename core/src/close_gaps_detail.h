// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// close_gaps() without the copy when nothing changes (repair's entry).

#include "meshbridge/close_gaps.h"

namespace meshbridge::detail {

// Fills `result` and returns true when gap closing changed the soup. Returns false, with only
// `result.report` filled (soup and origins empty), when nothing was welded or split.
// `known_boundary`, when given, holds the soup's boundary sides: the corners starting a side
// that no other side of the soup shares (vertex pair in either direction; sides from a vertex to
// itself excluded), sorted. Without it they are found here (one or two passes over the corners).
bool close_gaps_if_any(const Soup& soup, const CloseGapsOptions& options, ClosedGaps& result,
                       const std::vector<Index>* known_boundary = nullptr);

}  // namespace meshbridge::detail
