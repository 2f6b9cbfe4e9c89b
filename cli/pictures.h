// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pictures from the executable's side: the meshbridge_pictures module (Qt, cli/pictures_api.h) is
// found and loaded on the first picture only, so commands that draw nothing never load Qt.

#include "meshbridge/defect_report.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/soup.h"

#include "snapshot_options.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge::cli {

//! The meshbridge_pictures module is missing, cannot be loaded or is from another version. The
//! message starts "cannot draw pictures: " and names the paths tried or the loader's reason.
class PicturesUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! One picture for write_pictures_png: `soup` with its defects `report`, drawn as `options` say;
//! with `frame_soup` and `frame_report` (both or neither) framed as they would be. The pointers
//! are not owned and must outlive the call. With `crossings` (find_self_intersections(*soup)) its
//! faces are drawn violet.
struct Picture {
  const Soup* soup = nullptr;
  const DefectReport* report = nullptr;
  SnapshotOptions options;
  const Soup* frame_soup = nullptr;
  const DefectReport* frame_report = nullptr;
  const SelfIntersectionReport* crossings = nullptr;
};

//! What write_pictures_png drew (see DefectSnapshot in cli/defect_snapshot.h).
struct PicturesDrawn {
  std::size_t red_pixels = 0;     //!< summed over the pictures
  std::size_t green_pixels = 0;   //!< summed over the pictures
  std::size_t violet_pixels = 0;  //!< summed over the pictures (self-intersecting faces)
  bool legend_drawn = false;      //!< every picture has its legend
  //! The view of the first picture as drawn: the one chosen when its options said automatic (a
  //! later picture whose view is automatic is drawn along it too).
  SnapshotView view = SnapshotView::iso();
};

//! The module's file: the first that exists of meshbridge_pictures.so next to the executable (the
//! build tree) and in ../LIBDIR/meshbridge/ from the executable's folder (an installed copy;
//! LIBDIR is CMAKE_INSTALL_LIBDIR). Checks only that the file is there; commands call it before
//! their work so that a missing module is told at once.
//! \throw PicturesUnavailable "cannot draw pictures: meshbridge_pictures module not found in
//! FOLDER, FOLDER (looked for meshbridge_pictures.so)"
std::string find_pictures_module();

//! Draws `pictures` (at least one) side by side, left to right, into one PNG and writes it
//! atomically to `path`. Loads the module on the first call and keeps it loaded to the end of the
//! process (Qt's libraries do not unload cleanly).
//! \throw PicturesUnavailable when the module cannot be found or loaded
//! \throw std::bad_alloc when the image does not fit in memory
//! \throw WriteError naming `path` when the PNG cannot be encoded or written
//! \throw std::runtime_error with draw_defect_snapshot's message for a broken precondition
PicturesDrawn write_pictures_png(const std::string& path, const std::vector<Picture>& pictures);

}  // namespace meshbridge::cli
