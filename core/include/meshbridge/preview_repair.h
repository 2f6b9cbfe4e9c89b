// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file preview_repair.h
//! What repair() would do to a soup, so that `check` predicts `repair` (DESIGN 8a): `check`
//! exits 0 exactly when repair would change nothing, and shows every flip, weld, closing, cut
//! and split repair would make.

#include "meshbridge/defect_report.h"
#include "meshbridge/pairing.h"
#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <string>

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

//! Whether a repair with this report changed its input: a weld or crack closing, a polygon set
//! aside, split or removed, a vertex copy, a cut, a midpoint split, a reversed face, a hole
//! filled, or a vertex removed. Boundary edges, duplicate, zero-area and isolated elements that
//! the options keep are no change.
bool repair_changes_input(const RepairReport& report);

//! What repair() with given options would do to a soup.
struct RepairPreview {
  //! true: repair() ran in memory on the soup (RepairOptions::detect_before_after off) and
  //! `report` holds its counts, with `before`, `components_before` and `boundary_edges_before`
  //! from the detection given; `after` and the other `_after` counts are not computed (0).
  //! false: the soup is watertight with nothing the options remove or fill, so detection alone
  //! tells: only orientation can change it (`report.faces_flipped`,
  //! `report.ambiguous_nested_shells`; the other counts are the input's, `before` = `after` =
  //! the detection given).
  bool ran_repair = false;
  bool changes = false;  //!< repair_changes_input(report)
  RepairReport report;
};

//! What repair(soup, options) would change, without writing anything: the orientation preview
//! when the soup is watertight with nothing to remove or fill, else repair() itself run in memory
//! (its cost: a repair's time and peak memory, without the result's detection). `before` and
//! `orientation` are detect_defects(soup, &orientation, options.nested_shells) of the same soup.
//! \pre `soup` passes validate_soup() \throw as repair()
RepairPreview preview_repair(const Soup& soup, const DefectReport& before,
                             const OrientationPreview& orientation, const RepairOptions& options);

//! What `meshbridge check` reports of a soup (check_soup()).
struct SoupCheck {
  DefectReport report;             //!< detect_defects(soup)
  OrientationPreview orientation;  //!< as detect_defects(soup, &orientation, nested_shells)
  RepairPreview preview;           //!< preview_repair(soup, report, orientation, options)
};

//! detect_defects(soup, &orientation, options.nested_shells) and preview_repair() of its result,
//! with the same results, in one pass: the input is made simple and its sides grouped once, and
//! where repair has to run, the input's detection runs beside repair's pipeline on a second
//! thread (where there is one), as in repair(Soup&&). Cost: a detection on a watertight soup with
//! nothing to remove or fill; on any other, about a repair without writing and without the
//! result's detection. `options.progress` is not called.
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element; as
//! repair()
SoupCheck check_soup(const Soup& soup, const RepairOptions& options = {});

//! One line (with its newline) saying what repair would do: "repair would: make 13 vertex copies
//! (split fans), split 4 edges at the midpoint", or "repair would change nothing (16 boundary
//! edges stay open)".
std::string to_text(const RepairPreview& preview);

}  // namespace meshbridge
