// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Detection on an already grouped working soup, shared by detect_defects() and repair().

#include "meshbridge/defect_report.h"

#include "pipeline/grouping.h"
#include "working_soup.h"

#include <future>
#include <vector>

namespace meshbridge::detail {

//! Polygons of `soup` whose vertex set an earlier polygon has (all but the first of each set).
std::vector<Index> duplicate_polygons(const Soup& soup);

//! Detection on `working`, whose sides are `grouped` (as from group_sides(working.soup())).
DefectReport detect(const WorkingSoup& working, const GroupedSides& grouped);
//! Same, visiting the sides vertex pair by vertex pair without keeping a grouping (the least
//! memory: what detect_defects() runs). With `manifold_mate`, it receives the pairing of the
//! 2-sided edges (#C: the other side, or kNoIndex; pairs orientation could not make consistent
//! are cut, as detection counts non-orientable components). With `grouped_out`, the grouping made
//! on the way is kept there when the soup has a boundary or singular edge (then repair runs the
//! pipeline, which reads it: no second grouping); otherwise `grouped_out` is left empty.
DefectReport detect(const WorkingSoup& working, std::vector<Index>* manifold_mate = nullptr,
                    GroupedSides* grouped_out = nullptr);
//! detect(working, manifold_mate, grouped_out) for repair, which needs the grouping at once and
//! the report only after its pipeline: when the grouping is kept (the pipeline will run) and
//! `alongside` is set, the grouping and the per-edge tally are made here and the rest of the
//! detection (fans, components, orientability, faces) runs on a thread of its own, with a
//! corner-to-face map of its own since the pipeline frees the grouping; `manifold_mate` is then
//! left empty. Otherwise the report is made here and the future is ready. The thread reads
//! `working`, which must outlive the future (its destructor waits for the thread). A soup with
//! no boundary or singular edge has its face checks made on one thread (repair's peak memory),
//! or with `closed_in_parallel` on the worker threads as detect() makes them (check's time).
std::future<DefectReport> detect_alongside(const WorkingSoup& working,
                                           std::vector<Index>* manifold_mate,
                                           GroupedSides* grouped_out, bool alongside,
                                           bool closed_in_parallel = false);

}  // namespace meshbridge::detail
