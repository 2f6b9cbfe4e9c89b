// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The boundary between the `meshbridge` executable and the meshbridge_pictures module, the MODULE
// library that draws the PNG pictures with Qt. The executable does not link Qt: it dlopen()s the
// module (cli/pictures.h) only when a command draws (`snapshot`, `repair --before-after`), so every
// other command runs without Qt's libraries in memory.
//
// One entry point with C linkage returns a table of functions. No Qt type crosses: the executable
// passes the core's Soup and DefectReport and a SnapshotOptions by pointer, and gets the picture
// back as PNG bytes. Both sides are built from the same tree by the same compiler; the table's
// `abi` catches a module left over from another version. No C++ exception crosses either: every
// failure comes back as a status and a message.

#include "meshbridge/defect_report.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/soup.h"

#include "snapshot_options.h"

#include <cstddef>

extern "C" {

//! The version of everything in this header; bumped whenever a struct or a function changes.
#define MESHBRIDGE_PICTURES_ABI 3
//! The name of the one symbol the module exports (a MeshbridgePicturesEntry).
#define MESHBRIDGE_PICTURES_ENTRY "meshbridge_pictures_api"

//! One picture: `soup` with its defects `report`, drawn as draw_defect_snapshot draws it
//! (cli/defect_snapshot.h). Every pointer stays owned by the caller.
struct MeshbridgePictureRequest {
  const meshbridge::Soup* soup;                     //!< not null; passes validate_soup()
  const meshbridge::DefectReport* report;           //!< not null; detect_defects(*soup)
  const meshbridge::cli::SnapshotOptions* options;  //!< not null
  //! Null, or the soup and report whose framing is used instead (the "before" of a before/after
  //! pair, so both pictures line up); both set or both null.
  const meshbridge::Soup* frame_soup;
  const meshbridge::DefectReport* frame_report;
  //! Null, or find_self_intersections(*soup): its faces are drawn violet.
  const meshbridge::SelfIntersectionReport* crossings;
};

//! How draw_png ended.
enum MeshbridgePicturesStatus {
  MESHBRIDGE_PICTURES_OK = 0,
  MESHBRIDGE_PICTURES_OUT_OF_MEMORY = 1,  //!< the image or its PNG did not fit in memory
  MESHBRIDGE_PICTURES_BAD_INPUT = 2,      //!< a request broke a precondition; `error` says which
  MESHBRIDGE_PICTURES_ENCODE_FAILED = 3   //!< Qt could not encode the PNG; `error` says why
};

//! What draw_png made. Filled by the module; give it back to `release` once read.
struct MeshbridgePictureResult {
  int status;                 //!< a MeshbridgePicturesStatus
  char* error;                //!< NUL-terminated message unless status is OK, else null
  unsigned char* png;         //!< the PNG file's bytes when status is OK, else null
  std::size_t png_size;       //!< bytes at `png`
  std::size_t red_pixels;     //!< DefectSnapshot::red_pixels, summed over the pictures
  std::size_t green_pixels;   //!< DefectSnapshot::green_pixels, summed over the pictures
  std::size_t violet_pixels;  //!< DefectSnapshot::violet_pixels, summed over the pictures
  int legend_drawn;           //!< 1 when every picture has its legend (text renders here)
  //! The view the first picture was drawn along (chosen there when its options asked for auto).
  meshbridge::cli::SnapshotView view;
};

//! The module's functions.
struct MeshbridgePicturesApi {
  int abi;  //!< MESHBRIDGE_PICTURES_ABI as the module was built
  //! Draws the `count` >= 1 pictures side by side, left to right, with a 2-pixel grey rule between
  //! them (side_by_side in cli/defect_snapshot.h), and encodes the result as PNG. A later picture
  //! whose view is automatic takes the view chosen for the first (a before/after pair lines up;
  //! the "after" is framed on the "before" anyway). Qt runs on its
  //! "offscreen" platform (no display needed) for the duration of the call. Never throws.
  void (*draw_png)(const MeshbridgePictureRequest* pictures, std::size_t count,
                   MeshbridgePictureResult* result);
  //! Frees what draw_png put in `result` and clears it.
  void (*release)(MeshbridgePictureResult* result);
};

//! The type of the entry point MESHBRIDGE_PICTURES_ENTRY: the module's table, valid as long as the
//! module is loaded.
typedef const MeshbridgePicturesApi* (*MeshbridgePicturesEntry)(void);

}  // extern "C"
