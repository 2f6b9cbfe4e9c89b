// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/read_accounting.h"

namespace meshbridge {

void count_records_without_corners(const ReadInfo& info, DefectReport& report) {
  report.records_without_corners = info.faces_without_corners;
}

void count_records_without_corners(const ReadInfo& info, RepairReport& report) {
  report.faces_in += info.faces_without_corners;
  report.faces_set_aside += info.faces_without_corners;
  count_records_without_corners(info, report.before);
}

}  // namespace meshbridge
