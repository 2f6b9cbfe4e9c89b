// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file preview_repair.h
//! Detection that also says what repair's orientation would do, so that `check` predicts
//! `repair` (DESIGN 8a): a clean, closed mesh wound inside out is no "clean" model.

#include "meshbridge/defect_report.h"
#include "meshbridge/pairing.h"
#include "meshbridge/soup.h"

#include <cstddef>

namespace meshbridge {

//! What repair()'s orientation stage would do to a watertight soup.
struct OrientationPreview {
  bool computed = false;          //!< false: the soup is not watertight (repair's pipeline decides)
  std::size_t faces_flipped = 0;  //!< faces repair would reverse (RepairReport::faces_flipped)
  //! Closed shells nested in a closed shell and wound like it (RepairReport's count of the same
  //! name): ambiguous between an insert and a wrongly wound cavity.
  std::size_t ambiguous_nested_shells = 0;
};

//! detect_defects(soup), and when the report is watertight (and `orientation` is given) what
//! repair with RepairOptions::orient and `nested` would reverse there: each closed shell
//! outward, nested shells by their nesting and their own winding (orient_components() in
//! core/src/pipeline/orientation.h). Costs one orientation pass over a watertight soup on top of
//! detection; nothing on any other. \pre `soup` passes validate_soup()
//! \throw InvalidSoupError naming the offending element
DefectReport detect_defects(const Soup& soup, OrientationPreview* orientation,
                            AmbiguousNesting nested = AmbiguousNesting::material);

}  // namespace meshbridge
