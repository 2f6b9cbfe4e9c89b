// SPDX-License-Identifier: GPL-3.0-or-later
// Face records a file declares with no corner at all (an OFF face line "0", an OBJ "f" alone)
// are in no soup; these fold them into the reports of that soup, so that a report's faces and
// faces set aside, has_defects() and the exit codes agree with what the file declared.

#pragma once

#include "meshbridge/defect_report.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"

namespace meshbridge {

//! Counts `info.faces_without_corners` in `report`: DefectReport::records_without_corners
//! (which adds them to its faces and faces set aside, and makes them a defect).
void count_records_without_corners(const ReadInfo& info, DefectReport& report);

//! Counts `info.faces_without_corners` in a repair's report: in `faces_in` and
//! `faces_set_aside` (not written), and in `before` as above.
void count_records_without_corners(const ReadInfo& info, RepairReport& report);

}  // namespace meshbridge
