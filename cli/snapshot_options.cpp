// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_options.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdlib>
#include <stdexcept>

namespace meshbridge::cli {

namespace {

std::string lower(std::string text) {
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

SnapshotView parse_snapshot_view(const std::string& text) {
  const std::string name = lower(text);
  if (name == "auto")
    return SnapshotView::automatic_view();
  if (name == "iso")
    return SnapshotView::iso();
  // Signed axes: "x", "+x", "-x+y+z"; each axis at most once, a sign before all but a lone one.
  SnapshotView view{false, 0, 0, 0};
  std::size_t i = 0, axes = 0;
  bool bare = false;
  while (i < name.size()) {
    int sign = 1;
    if (name[i] == '+' || name[i] == '-')
      sign = name[i++] == '-' ? -1 : 1;
    else
      bare = true;
    int* axis = nullptr;
    if (i < name.size() && name[i] >= 'x' && name[i] <= 'z')
      axis = name[i] == 'x' ? &view.x : name[i] == 'y' ? &view.y : &view.z;
    if (axis == nullptr || *axis != 0) {
      axes = 0;
      break;
    }
    *axis = sign;
    ++i, ++axes;
  }
  if ((axes == 1 || (axes == 3 && !bare)) && view.is_valid())
    return view;
  throw std::invalid_argument(
      "view must be auto, iso, x, y, z, -x, -y, -z or a corner such as "
      "-x+y+z, got '" +
      text + "'");
}

void add_view_options(CLI::App& command, std::string& view, std::string& focus, std::string& up) {
  command
      .add_option("--view", view,
                  "look from: auto (default) = of iso, the other seven corners and the six "
                  "axes, the view that shows the most defect pixels; iso (above the +x+y "
                  "corner); x, y, z, -x, -y, -z (along that axis); or a corner such as -x+y+z")
      ->transform(CLI::Validator(
          [](std::string& text) {
            try {
              text = to_string(parse_snapshot_view(text));
              return std::string();
            } catch (const std::invalid_argument&) {
              return text + " is not auto, iso, x, y, z, -x, -y, -z or a corner such as -x+y+z";
            }
          },
          "VIEW"));
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

std::string to_string(const SnapshotView& view) {
  if (view.automatic)
    return "auto";
  if (view == SnapshotView::iso())
    return "iso";
  const bool axis = std::abs(view.x) + std::abs(view.y) + std::abs(view.z) == 1;
  std::string name;
  const char* letters = "xyz";
  const int signs[] = {view.x, view.y, view.z};
  for (int i = 0; i < 3; ++i) {
    if (signs[i] != 0)
      name += std::string(signs[i] < 0 ? "-" : (axis ? "" : "+")) + letters[i];
  }
  return name;
}

}  // namespace meshbridge::cli
