// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_options.h"

#include <stdexcept>

namespace meshbridge::cli {

SnapshotView parse_snapshot_view(const std::string& text) {
  if (text == "iso")
    return SnapshotView::iso;
  if (text == "x")
    return SnapshotView::x;
  if (text == "y")
    return SnapshotView::y;
  if (text == "z")
    return SnapshotView::z;
  throw std::invalid_argument("view must be iso, x, y or z, got '" + text + "'");
}

const char* to_string(SnapshotView view) {
  switch (view) {
    case SnapshotView::iso:
      return "iso";
    case SnapshotView::x:
      return "x";
    case SnapshotView::y:
      return "y";
    case SnapshotView::z:
      return "z";
  }
  throw std::invalid_argument("unknown snapshot view");
}

}  // namespace meshbridge::cli
