// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// close_gaps() without the copy when nothing changes (repair's entry).

#include "meshbridge/close_gaps.h"

namespace meshbridge::detail {

// Fills `result` and returns true when gap closing changed the soup. Returns false, with only
// `result.report` filled (soup and origins empty), when nothing was welded or split.
bool close_gaps_if_any(const Soup& soup, const CloseGapsOptions& options, ClosedGaps& result);

}  // namespace meshbridge::detail
