// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a snapshot looks like: the view, the framing, the size and the legend. No Qt here: the
// commands take these options without Qt, and the drawing (cli/defect_snapshot.h) uses them.

#include <string>

namespace CLI {
class App;
}

namespace meshbridge::cli {

//! The direction the orthographic camera looks from (always toward the model's centre), in the
//! model's frame as drawn (with SnapshotOptions::y_up, +y of the file counts as +z). Either
//! `automatic`, or a side given by the signs `x`, `y`, `z` (each -1, 0 or +1): all three nonzero
//! is a corner, seen as iso is (azimuth toward that corner, elevation 30 deg up or down, +z up
//! on screen); exactly one nonzero is along that axis (+z up on screen for the four sides, +y for
//! the top and bottom views). No other combination is a view.
struct SnapshotView {
  //! Choose the view (choose_view in cli/snapshot_views.h): the candidate that shows the most
  //! defect pixels, iso on a tie. Default true; x, y, z are then ignored.
  bool automatic = true;
  int x = 1, y = 1, z = 1;

  static SnapshotView automatic_view() { return {}; }
  //! From about +(1,1,1): azimuth 45 deg (from +x toward +y), elevation 30 deg, +z up; a little
  //! below the exact isometric (35.26 deg), where a box's back corner hides behind its front one.
  static SnapshotView iso() { return {false, 1, 1, 1}; }
  //! Along one axis: `axis` 0, 1 or 2 (x, y, z) from the side `sign` (+1 or -1). From +x, +y is to
  //! the right; from +y, -x; from +z (top view), +x with +y up.
  static SnapshotView along(int axis, int sign) {
    return {false, axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0};
  }
  //! True for a corner or an axis view with signs in {-1, 0, 1}, or automatic.
  bool is_valid() const {
    if (automatic)
      return true;
    const bool signs = x >= -1 && x <= 1 && y >= -1 && y <= 1 && z >= -1 && z <= 1;
    const int nonzero = (x != 0) + (y != 0) + (z != 0);
    return signs && (nonzero == 1 || nonzero == 3);
  }
  bool operator==(const SnapshotView& other) const {
    return automatic == other.automatic &&
           (automatic || (x == other.x && y == other.y && z == other.z));
  }
  bool operator!=(const SnapshotView& other) const { return !(*this == other); }
};

//! Parses "auto", "iso", an axis ("x", "+x", "-x", likewise y and z) or a corner ("+x+y+z" is
//! iso, "-x+y+z", "+x-y-z", ...), case-insensitive.
//! \throw std::invalid_argument naming the text otherwise
SnapshotView parse_snapshot_view(const std::string& text);
//! "auto", "iso", "x", "-x", ..., "z", "-z", or a corner other than iso as "-x+y+z"; every
//! name parses back to the same view.
std::string to_string(const SnapshotView& view);

//! What the picture is fitted to.
enum class SnapshotFocus {
  //! defects when their box is under a quarter of the model across on screen, framed with at
  //! least 0.4 of the model's width around them so the model stays readable; else whole
  //! (default)
  automatic,
  whole,   //!< the whole model
  defects  //!< the bounding box of the singular and boundary edges and pinch vertices (the whole
           //!< model when there is no such defect)
};

//! Adds `--view auto|iso|x|y|z|-x|...|-x+y+z|...`, `--focus auto|whole|defects` and `--up z|y`
//! to `command` (snapshot, and repair for --before-after), storing their text (checked with
//! parse_snapshot_view for --view); read them with parse_snapshot_view,
//! parse_snapshot_focus and `up == "y"`.
void add_view_options(CLI::App& command, std::string& view, std::string& focus, std::string& up);
//! Parses "auto", "whole" or "defects". \throw std::invalid_argument naming the text otherwise
SnapshotFocus parse_snapshot_focus(const std::string& text);

//! Options of draw_defect_snapshot, every default documented.
struct SnapshotOptions {
  //! Width and height of the square image in pixels (default 800); kMinSize .. kMaxSize.
  int size = 800;
  static constexpr int kMinSize = 16;
  static constexpr int kMaxSize = 8192;
  //! Default automatic: the candidate view that shows the most defect pixels (iso on a tie).
  SnapshotView view = SnapshotView::automatic_view();
  //! Blank border on every side, as a fraction of `size` (default 0.05).
  double margin = 0.05;
  SnapshotFocus focus = SnapshotFocus::automatic;  //!< default automatic
  //! The model's up axis is +y (as Blender's OBJ export, glTF, many scanners write it), not +z:
  //! the views turn with it (`z` still looks down on the model). Default false: +z up.
  bool y_up = false;
  //! Draw the legend line of counts at the top (default true). It is left out anyway when no
  //! QGuiApplication exists or text does not render (no font found offscreen).
  bool legend = true;
  //! Starts the legend, e.g. the file name (default empty: counts only).
  std::string title;
};

}  // namespace meshbridge::cli
