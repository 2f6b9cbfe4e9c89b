// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a snapshot looks like: the view, the framing, the size and the legend. No Qt here: the
// commands take these options without Qt, and the drawing (cli/defect_snapshot.h) uses them.

#include <string>

namespace CLI {
class App;
}

namespace meshbridge::cli {

//! The direction the orthographic camera looks from (always toward the model's centre).
enum class SnapshotView {
  //! from about +(1,1,1): azimuth 45 deg (from +x toward +y), elevation 30 deg, +z up; a little
  //! below the exact isometric (35.26 deg), where a box's back corner hides behind its front one
  iso,
  x,  //!< from +x, +z up, +y to the right
  y,  //!< from +y, +z up, -x to the right
  z   //!< from +z (top view), +y up, +x to the right
};

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

//! Parses "iso", "x", "y" or "z". \throw std::invalid_argument naming the text otherwise
SnapshotView parse_snapshot_view(const std::string& text);
//! "iso", "x", "y" or "z".
const char* to_string(SnapshotView view);

//! Adds `--view iso|x|y|z`, `--focus whole|defects` and `--up z|y` to `command` (snapshot, and
//! repair for --before-after), storing their text; read them with parse_snapshot_view,
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
  SnapshotView view = SnapshotView::iso;  //!< default iso
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
