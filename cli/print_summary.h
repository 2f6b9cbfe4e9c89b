// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What is still open in a repaired file and why: the `print:` paragraph of `repair --print` and
// the `hint:` line of a plain repair.

#include "meshbridge/defect_report.h"
#include "meshbridge/repair.h"

#include <string>

namespace meshbridge::cli {

//! The `print:` paragraph of the summary: whether the written mesh is watertight, and for each
//! open edge left the reason (holes longer than the filling's limit, outlines of open sheets,
//! boundaries of odd singular edges, gap closing refused) with the option that would change it.
//! `written` (may be null): detection on the file as written when that differs from the repaired
//! polygons (an STL re-read, a 3MF's triangles).
std::string print_summary(const RepairReport& report, const DefectReport* written = nullptr);

//! For a repair without --print that leaves open edges: one `hint:` line naming them and what
//! would close them (--fill-holes when filling was off, --print); "" when the result is closed.
std::string open_edges_hint(const RepairReport& report);

}  // namespace meshbridge::cli
