// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair_file.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/polygon_triangles.h"
#include "meshbridge/print_preset.h"
#include "meshbridge/read_accounting.h"
#include "meshbridge/separate_copies.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace meshbridge {

namespace {

void tell(const RepairFileOptions& options, Stage stage) {
  if (options.repair.progress)
    options.repair.progress(stage, 0);
}

// The split copies moved apart before `mesh` is written to `out` (RepairFileOptions::separation).
StlSeparation separate(IndexedMesh& mesh, std::size_t vertices_split, const std::string& out,
                       double separation) {
  const bool stl = mesh_format(out) == MeshFormat::stl;
  if (vertices_split == 0 || separation == 0 || (separation < 0 && !stl))
    return StlSeparation();
  if (separation < 0)
    return separate_copies_for_stl(mesh);
  if (stl) {
    IndexedMesh trial = mesh;
    separate_split_vertices(trial, separation);
    if (singular_elements_after_stl_round_trip(trial.soup) != 0) {
      std::ostringstream message;
      message << "--separate " << separation << " is too small for float32 (STL) at this model's "
              << "coordinates: the copies would weld again; the smallest EPS that works is "
              << smallest_stl_separation(mesh) << " (or use --separate auto)";
      throw std::invalid_argument(message.str());
    }
  }
  StlSeparation done;
  done.distance = separation;
  done.vertices_moved = separate_split_vertices(mesh, separation);
  return done;
}

// RepairFileOptions::create_folder.
void create_folder_of(const std::string& out) {
  const std::filesystem::path folder = std::filesystem::path(out).parent_path();
  if (folder.empty())
    return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw WriteError(folder.string() + ": cannot create the folder (" + error.message() + ")");
  }
  if (::access(folder.c_str(), W_OK) != 0)
    throw WriteError(folder.string() + ": cannot write here (" + std::strerror(errno) + ")");
}

}  // namespace

RepairedFile repair_file(const std::string& in, const std::string& out,
                         const RepairFileOptions& options) {
  RepairedFile file;
  repair_file(in, out, options, file);
  return file;
}

void repair_file(const std::string& in, const std::string& out, const RepairFileOptions& options,
                 RepairedFile& file) {
  file = RepairedFile();
  tell(options, Stage::read);
  MeshAttributes attributes;
  Soup soup = read_soup(in, &file.info, &attributes);
  file.read = true;
  RepairOptions repair_options = options.repair;
  repair_options.close_gaps.float_coordinates = file.info.float_coordinates;
  RepairResult result;
  if (options.print) {
    apply_print_preset(soup, options.print_keeps_weld, options.print_keeps_fill_holes,
                       repair_options);
    result = repair_for_print(soup, repair_options, file.print_note);
  } else if (options.keep_meshes) {
    result = repair(soup, repair_options);
  } else {
    result = repair(std::move(soup), repair_options);  // an unchanged input becomes the output
  }
  if (options.keep_meshes)
    file.input = std::move(soup);
  soup = Soup();  // what repair left of it, freed before the output is written
  if (options.repaired)
    options.repaired();
  count_records_without_corners(file.info, result.report);  // face records with no corner
  if (options.create_folder)
    create_folder_of(out);
  tell(options, Stage::write);
  file.separated = separate(result.mesh, result.report.vertices_split, out, options.separation);
  if (options.self_intersections)  // of the mesh as written (copies moved apart included)
    file.crossings = find_self_intersections(result.mesh.soup);
  write_mesh(out, result.mesh, &attributes);  // maps them through the mesh's origins
  file.written = describe_written(out, result.mesh, attributes, result.report.gaps.vertices_welded);
  file.written.copies_moved = file.separated.vertices_moved;
  file.written.separation = file.separated.distance;
  std::error_code status_error;  // (a device or pipe cannot be read back)
  if (mesh_format(out) == MeshFormat::stl && std::filesystem::is_regular_file(out, status_error)) {
    // STL keeps no shared vertices: the file as a reader gets it back. Without keep_meshes the
    // mesh is freed first, so the peak is not the mesh and the re-read soup together.
    if (options.keep_meshes) {
      file.written_soup = read_soup(out);
      file.reread = detect_defects(file.written_soup);
    } else {
      result.mesh = IndexedMesh();
      file.reread = detect_defects(read_soup(out));
    }
  } else if (mesh_format(out) == MeshFormat::threemf && file.written.polygons_triangulated > 0) {
    // The file holds triangles: detection on them, as any reader of the 3MF gets them.
    file.reread = detect_defects(as_triangles(result.mesh.soup));
  }
  file.report = std::move(result.report);
  if (options.keep_meshes)
    file.mesh = std::move(result.mesh);
}

}  // namespace meshbridge
