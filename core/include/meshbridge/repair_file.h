// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file repair_file.h
//! The one route from a mesh file to a repaired mesh file: read, repair, move STL copies apart,
//! write atomically, and detect what a reader of the written file gets. `meshbridge repair`,
//! `meshbridge batch` (run_file_job()), Python's `meshbridge.batch` (run_file_job() too) and
//! the Dask batch all take it, so one file gives the same output and counts on every route.
//! (Python's meshbridge.read/repair/write work on soups in memory; write() moves an STL's
//! split copies apart with the same separate_copies_for_stl().)

#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/stl_round_trip.h"

#include <functional>
#include <optional>
#include <string>

namespace meshbridge {

//! RepairFileOptions::separation: the smallest move that survives a reader's weld (STL only).
inline constexpr double kAutoSeparation = -1;

//! What repair_file() does besides repair(). Defaults: the full repair, STL copies moved apart
//! automatically, no preset, no self-intersection search.
struct RepairFileOptions {
  //! The repair. `repair.close_gaps.float_coordinates` is set from the file read (ReadInfo).
  RepairOptions repair;
  //! The slicer preset (print_preset.h): apply_print_preset() on the soup read, then
  //! repair_for_print(). With `print_keeps_weld` / `print_keeps_fill_holes` the preset leaves
  //! `repair.close_gaps.tolerance` / `repair.fill_holes` as given (the user chose them).
  bool print = false;
  bool print_keeps_weld = false;
  bool print_keeps_fill_holes = false;
  //! How far each copy of a split vertex moves into its own fan before writing, in model units:
  //! kAutoSeparation (default) = for STL output the smallest distance a float32 re-read and its
  //! default weld keep apart (separate_copies_for_stl()), nothing for formats that keep shared
  //! vertices; 0 = positions exact (an STL reader welds the copies again: see
  //! RepairedFile::reread); > 0 = this distance, for any format.
  double separation = kAutoSeparation;
  //! Also find the faces of the mesh as written that cross or overlap (RepairedFile::crossings).
  bool self_intersections = false;
  //! Keep the soup read (RepairedFile::input), the repaired mesh, and for STL output the file as
  //! read back (RepairedFile::written_soup): for pictures. Off: each is freed as soon as it is
  //! not needed, so the peak is one of them at a time.
  bool keep_meshes = false;
  //! Create the output's folder (and its parents) when missing, after the repair; a folder that
  //! cannot be made or written is a WriteError naming it. Off: a missing folder is the writer's
  //! WriteError.
  bool create_folder = false;
  //! Called after the repair, before the output is written (the CLI returns freed memory to the
  //! system there). Empty: not called.
  std::function<void()> repaired;
};

//! What repair_file() read, did and wrote.
struct RepairedFile {
  bool read = false;    //!< the input was read: `info` holds what the reader found
  ReadInfo info;        //!< what the reader found (read_soup())
  RepairReport report;  //!< what the repair did (records without corners counted in)
  //! `print`: why removals were taken back (repair_for_print()); empty otherwise.
  std::string print_note;
  StlSeparation separated;  //!< the split copies moved before writing (none: all 0)
  WrittenOutput written;    //!< describe_written() of the output, with the move
  //! Detection on the file as a reader gets it, where that differs from the repaired polygons:
  //! an STL read back (no shared vertices: unmoved copies weld again), or a 3MF whose polygons
  //! were cut into triangles. Empty otherwise.
  std::optional<DefectReport> reread;
  std::optional<SelfIntersectionReport> crossings;  //!< with `self_intersections`
  Soup input;                                       //!< with `keep_meshes`: the soup read
  IndexedMesh mesh;                                 //!< with `keep_meshes`: the mesh written
  Soup written_soup;  //!< with `keep_meshes` and STL output: the file as read back
};

//! Reads `in`, repairs it, writes `out` atomically (the extension names the format) with the
//! input's attributes carried through the origins (carry_attributes()), and fills the rest of
//! RepairedFile. `options.repair.progress`, when set, is also told of Stage::read and
//! Stage::write.
//! \throw ReadError, InvalidSoupError as read_soup(); WriteError as write_mesh()
//! \throw std::invalid_argument when `options.separation` > 0 is too small for an STL output:
//!        float32 positions would weld the copies again (the message names the smallest that
//!        works); nothing is written then
RepairedFile repair_file(const std::string& in, const std::string& out,
                         const RepairFileOptions& options = {});

//! repair_file() into `file`, filled as it goes: when it throws, what was done stays (`file.info`
//! once the file was read, for a record that names what the reader found).
void repair_file(const std::string& in, const std::string& out, const RepairFileOptions& options,
                 RepairedFile& file);

}  // namespace meshbridge
