// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_options.h"

#include <CLI/CLI.hpp>

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

void add_view_options(CLI::App& command, std::string& view, std::string& focus, std::string& up) {
  command
      .add_option("--view", view, "look from: iso (above a corner), x, y or z (along that axis)")
      ->transform(CLI::IsMember({"iso", "x", "y", "z"}, CLI::ignore_case));
  command
      .add_option("--focus", focus,
                  "auto (default) = zoom toward the defects when they are small, the whole "
                  "model otherwise; whole = fit the whole model; defects = zoom to the box "
                  "around the singular and boundary edges and pinch vertices")
      ->transform(CLI::IsMember({"auto", "whole", "defects"}, CLI::ignore_case));
  command
      .add_option("--up", up,
                  "the model's up axis: z (default) or y (a y-up OBJ otherwise lies on its side)")
      ->transform(CLI::IsMember({"z", "y"}, CLI::ignore_case));
}

SnapshotFocus parse_snapshot_focus(const std::string& text) {
  if (text == "auto")
    return SnapshotFocus::automatic;
  if (text == "whole")
    return SnapshotFocus::whole;
  if (text == "defects")
    return SnapshotFocus::defects;
  throw std::invalid_argument("focus must be auto, whole or defects, got '" + text + "'");
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
