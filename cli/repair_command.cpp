// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"
#include "paths.h"
#include "pictures.h"
#include "print_summary.h"
#include "printer_options.h"
#include "progress.h"
#include "release_memory.h"
#include "validators.h"

#include "meshbridge/counted.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/repair_file.h"
#include "meshbridge/report_json.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <optional>

namespace meshbridge::cli {

namespace {

void write_text_atomically(const std::string& path, const std::string& text) {
  write_bytes_atomically(path, text);  // unique temporary beside `path`, renamed on success
}

struct RepairArguments {
  std::string in, out, report;
  std::string pairing = "geometric";
  bool no_orient = false, no_stitch = false;
  bool elements = false;
  bool progress = false;
  bool in_place = false;            //!< OUT may be IN itself
  bool self_intersections = false;  //!< also find the crossing faces of the result
  std::string before_after;
  std::string view;   //!< --view for --before-after ("" = iso)
  std::string focus;  //!< --focus for --before-after ("" = whole)
  std::string up;     //!< --up for --before-after ("" = z)
  RepairOptions options;
  //! "auto" (default: for STL, the smallest move that survives a reader's weld) or a distance
  //! >= 0 (0 = positions exact)
  std::string separate = "auto";
  bool separate_given = false;  //!< --separate was on the command line
  bool print = false;           //!< --print: the slicer preset (print_preset.h)
  bool weld_given = false, fill_holes_given = false;
  std::string weld = "auto";  //!< "auto" or a distance >= 0 (0 = off)
  std::string fill_holes;     //!< MAX_EDGES of --fill-holes ("" or "0" = off)
};

//! A report on standard output ('-', /dev/stdout or the file stdout goes to) is printed there,
//! and the summary moves to standard error, so that stdout holds the JSON alone.
bool report_to_stdout(const RepairArguments& arguments) {
  return arguments.report == "-" || is_standard_output(arguments.report);
}

//! The usage errors that can be told before anything is read: an unknown or unwritable OUT,
//! OUT = IN without --in-place, --print without a .3mf, a --report that names a mesh, picture
//! options without --before-after. \throws UsageError
void check_arguments(const RepairArguments& arguments) {
  const std::string& in = arguments.in;
  const std::string& out = arguments.out;
  std::error_code folder_error;
  if (std::filesystem::is_directory(out, folder_error))
    check_writable_file(out);  // "OUT: cannot write: it is a folder", not "unknown format"
  if (!is_supported_mesh_file(out)) {
    throw UsageError(out + ": unknown output format (expected .obj, .off, .ply, .stl or .3mf)");
  }
  if (arguments.print && mesh_format(out) != MeshFormat::threemf) {
    throw UsageError(out +
                     ": --print writes 3MF, the format slicers read with units, objects "
                     "and no re-weld; name OUT .3mf");
  }
  check_readable_file(in);
  std::error_code same_error;  // (an OUT that does not exist yet is not IN)
  if (!arguments.in_place && std::filesystem::equivalent(in, out, same_error)) {
    throw UsageError(out +
                     ": is the input file itself; repair would replace it (pass --in-place "
                     "to allow that, or name another output)");
  }
  check_writable_file(out);
  if (!arguments.report.empty() && !report_to_stdout(arguments)) {
    // The report must not replace the mesh read or the mesh written.
    for (const std::string* mesh : {&in, &out}) {
      std::error_code same;
      if (arguments.report == *mesh || std::filesystem::equivalent(arguments.report, *mesh, same))
        throw UsageError(arguments.report + ": --report names the " +
                         (mesh == &in ? "input" : "output") + " mesh; name another file");
    }
    check_writable_file(arguments.report);
  }
  if (arguments.before_after.empty() && !(arguments.view + arguments.focus + arguments.up).empty())
    throw UsageError(std::string(!arguments.view.empty()    ? "--view"
                                 : !arguments.focus.empty() ? "--focus"
                                                            : "--up") +
                     " draws the --before-after picture: give --before-after PIC.png too");
  if (!arguments.before_after.empty()) {
    if (!ends_with_png(arguments.before_after)) {
      throw UsageError(arguments.before_after + ": --before-after is written as PNG; name it .png");
    }
    check_writable_file(arguments.before_after);
    find_pictures_module();  // a missing module is told now, not after the repair
  }
}

//! The options of repair_file() from the command line.
RepairFileOptions file_options_of(const RepairArguments& arguments) {
  RepairOptions options = arguments.options;
  options.pairing = arguments.pairing == "combinatorial" ? PairingPolicy::combinatorial
                                                         : PairingPolicy::geometric;
  options.orient = !arguments.no_orient;
  options.stitch = !arguments.no_stitch;
  options.close_gaps = parse_weld(arguments.weld);
  options.fill_holes.max_edges = parse_fill_holes(arguments.fill_holes);
  RepairFileOptions file_options;
  file_options.repair = options;
  file_options.print = arguments.print;
  file_options.print_keeps_weld = arguments.weld_given;
  file_options.print_keeps_fill_holes = arguments.fill_holes_given;
  file_options.separation = parse_separation(arguments.separate);
  file_options.self_intersections = arguments.self_intersections;
  file_options.keep_meshes = !arguments.before_after.empty();  // only the picture reads them
  file_options.repaired = release_free_memory;  // the repair's working arrays, before writing
  return file_options;
}

//! The JSON report (--report) on stdout or written atomically to its file.
//! \throws WriteError naming the report (OUT is written by then)
void write_report(const RepairArguments& arguments, const RepairedFile& file, bool to_stdout) {
  const std::string& in = arguments.in;
  const std::string& out = arguments.out;
  const RepairReport& report = file.report;
  const DefectReport* reread = file.reread ? &*file.reread : nullptr;
  ReportJsonOptions json;
  json.elements = arguments.elements;
  const std::string text =
      repair_report_json(in, out, report, &file.info, json, reread, &file.written,
                         file.crossings ? &*file.crossings : nullptr) +
      "\n";
  if (to_stdout) {
    std::cout << text << std::flush;
  } else {
    try {
      write_text_atomically(arguments.report, text);
    } catch (const WriteError& error) {
      // Name what failed: the report, after OUT was written.
      std::string why = error.what();
      const std::string prefix = arguments.report + ": ";
      if (why.compare(0, prefix.size(), prefix) == 0)
        why.erase(0, prefix.size());
      throw WriteError(arguments.report + ": cannot write the report (" + why + "); " + out +
                       " is written");
    }
  }
}

//! The --before-after picture; returns the view drawn ("auto -> NAME" when chosen).
std::string draw_before_after(const RepairArguments& arguments, const RepairedFile& file) {
  const std::string& in = arguments.in;
  const std::string& out = arguments.out;
  const RepairReport& report = file.report;
  const DefectReport* reread = file.reread ? &*file.reread : nullptr;
  // The result framed as the input, so the two pictures line up; the file as a reader gets
  // it back where that differs (STL).
  const bool reread_soup = !file.written_soup.positions.empty();
  Picture before, after;
  before.soup = &file.input;
  before.report = &report.before;
  before.options.title = "before: " + file_name_of(in);
  after.soup = reread_soup ? &file.written_soup : &file.mesh.soup;
  after.report = reread_soup ? reread : &report.after;
  after.options.title = "after: " + file_name_of(out);
  after.frame_soup = &file.input;
  after.frame_report = &report.before;
  // With --self-intersections the crossing faces are violet on both sides: the input's found
  // here, the result's are those of the mesh written, or found again on the STL read back.
  std::optional<SelfIntersectionReport> crossings_before, crossings_reread;
  if (arguments.self_intersections) {
    crossings_before = find_self_intersections(file.input);
    before.crossings = &*crossings_before;
    if (reread_soup) {
      crossings_reread = find_self_intersections(file.written_soup);
      after.crossings = &*crossings_reread;
    } else if (file.crossings) {
      after.crossings = &*file.crossings;
    }
  }
  for (Picture* picture : {&before, &after}) {
    picture->options.view = parse_snapshot_view(arguments.view.empty() ? "auto" : arguments.view);
    picture->options.focus =
        parse_snapshot_focus(arguments.focus.empty() ? "auto" : arguments.focus);
    picture->options.y_up = arguments.up == "y";
  }
  const PicturesDrawn drawn = write_pictures_png(arguments.before_after, {before, after});
  return (before.options.view.automatic ? "auto -> " : "") + to_string(drawn.view);
}

//! The text summary: the report, STL separation, the preset's or the open edges' note,
//! self-intersections, triangulation, what a reader gets back, the picture's view.
void print_repair_summary(const RepairArguments& arguments, const RepairedFile& file,
                          const std::string& picture_view, std::ostream& summary) {
  const std::string& in = arguments.in;
  const std::string& out = arguments.out;
  const RepairReport& report = file.report;
  const DefectReport* reread = file.reread ? &*file.reread : nullptr;
  const WrittenOutput& written = file.written;
  summary << in << " -> " << out << "\n"
          << to_text(report)
          << separation_summary(file.separated, report.vertices_split, arguments.separate,
                                arguments.separate_given, out);
  if (arguments.print)
    summary << file.print_note << print_summary(report, reread);
  else
    summary << open_edges_hint(report);
  if (file.crossings)
    summary << "self-intersections of the result:\n" << to_text(*file.crossings);
  if (written.polygons_triangulated != 0) {
    summary << "written as " << written.triangles
            << " triangles: " << counted(written.polygons_triangulated, "polygon")
            << " cut into triangles (the format holds triangles only)\n";
  }
  if (reread) {
    // STL keeps no shared vertices, 3MF holds triangles: say what a reader gets from the file.
    const std::size_t left = reread->singular_edges.size() + reread->num_singular_vertices();
    summary << "as re-read from " << out << ": singular edges " << reread->singular_edges.size()
            << ", singular vertices " << reread->num_singular_vertices() << ", watertight "
            << (reread->watertight ? "yes" : "no") << "\n";
    if (left > 0 && !is_stl_path(out)) {
      std::cerr << "meshbridge: warning: " << out << " holds triangles only: cut into triangles, "
                << "the repaired polygons have "
                << counted(reread->singular_edges.size(), "singular edge") << " and "
                << counted(reread->num_singular_vertices(), "singular vertex")
                << " (polygons split at an edge's midpoint on both sides of one sheet share a "
                   "diagonal); write OBJ, PLY or OFF to keep the polygons.\n";
    } else if (left > 0) {
      std::cerr << "meshbridge: warning: STL has no shared vertices; reading " << out
                << " welds the " << report.vertices_split
                << " split vertex copies again and re-creates "
                << counted(reread->singular_edges.size(), "singular edge") << " and "
                << counted(reread->num_singular_vertices(), "singular vertex")
                << ". Leave out --separate (the default moves them apart), or write 3MF, PLY, "
                   "OBJ or OFF.\n";
    }
  }
  if (!picture_view.empty())
    summary << "before/after picture " << arguments.before_after << ": view " << picture_view
            << "\n";
}

int run_repair(RepairArguments& arguments) {
  check_arguments(arguments);
  RepairFileOptions file_options = file_options_of(arguments);
  RepairedFile file;
  {
    ProgressDisplay progress(arguments.in, progress_wanted(arguments.progress),
                             progress_wanted(false), repair_plan());
    file_options.repair.progress = progress.callback();
    try {
      file = repair_file(arguments.in, arguments.out, file_options);
    } catch (const std::invalid_argument& error) {  // --separate too small: nothing written
      throw UsageError(error.what());
    }
  }
  const bool to_stdout = report_to_stdout(arguments);
  if (!arguments.report.empty())
    write_report(arguments, file, to_stdout);
  const std::string picture_view =
      arguments.before_after.empty() ? std::string() : draw_before_after(arguments, file);
  warn_about_reader(arguments.in, file.info);
  for (const std::string& what : file.written.left_out) {
    std::cerr << "meshbridge: warning: " << arguments.in << ": output " << arguments.out << ": "
              << what << "\n";
  }
  print_repair_summary(arguments, file, picture_view, to_stdout ? std::cerr : std::cout);
  return kOk;
}

}  // namespace

void add_repair_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<RepairArguments>();
  RepairOptions& options = arguments->options;
  CLI::App* command = app.add_subcommand(
      "repair",
      "Lossless manifold repair of IN into OUT: every face is kept, every edge of the result is\n"
      "manifold. Exit 0 = written, 2 = error.");
  command->add_option("IN", arguments->in, "mesh to repair (.obj, .off, .ply, .stl, .3mf)")
      ->required();
  command
      ->add_option("OUT", arguments->out,
                   "where to write the result; the extension picks the format (.obj, .off, .ply, "
                   ".stl, .3mf); replaced atomically")
      ->required();
  command->add_option("--report", arguments->report,
                      "also write the repair report as JSON to this file "
                      "(docs/report-schema.md); '-' or /dev/stdout: to standard output, the "
                      "summary then going to standard error");
  command->add_flag("--elements", arguments->elements,
                    "with --report: also list the defective elements before and after; default "
                    "counts only");
  command
      ->add_option("--pairing", arguments->pairing,
                   "how the sides (contenders) at a singular edge pair up: geometric = by angle "
                   "around the edge, combinatorial = by face order")
      ->transform(CLI::IsMember({"geometric", "combinatorial"}, CLI::ignore_case));
  command->add_flag("--in-place", arguments->in_place,
                    "allow OUT to be IN itself (the input is replaced, atomically)");
  command->add_flag("--no-orient", arguments->no_orient,
                    "keep every face's corner order (default: orient each component "
                    "consistently, closed ones outward)");
  command->add_flag("--no-stitch", arguments->no_stitch,
                    "do not glue cut sides back together where that stays manifold");
  command->add_flag("--cut-nonorientable", options.cut_nonorientable,
                    "also orient non-orientable components (Moebius strips): faces take the "
                    "orientation of a breadth-first spanning tree, and the edges that disagree "
                    "with it are cut (not necessarily the fewest). Default: such a component "
                    "keeps its faces' directions and each edge whose faces run the same way is "
                    "cut (not necessarily the fewest either)");
  add_nested_shells_option(*command, options.nested_shells);
  command->add_flag("--remove-duplicates", options.remove_duplicate_faces,
                    "drop faces whose vertex set an earlier face has");
  command->add_flag("--remove-zero-area", options.remove_zero_area_faces,
                    "drop faces of (near) zero area: slivers and needles whose distinct corners "
                    "lie on one line (check's zero-area faces)");
  command->add_flag("--remove-degenerate", options.remove_degenerate_faces,
                    "drop faces that repeat a vertex");
  command->add_flag("--remove-isolated", options.remove_isolated_vertices,
                    "drop vertices that no kept face uses");
  command
      ->add_option("--weld", arguments->weld,
                   "TOL|auto: before pairing, weld boundary vertices closer than TOL (model units) "
                   "and split boundary sides at T-junction cracks; auto = per vertex 2^-21 x the "
                   "extent of its part (never the file's largest coordinate), at most a quarter "
                   "of the shortest edge at it; 0 = off")
      ->capture_default_str()
      ->check(distance_or_auto());
  CLI::Option* separate =
      command
          ->add_option("--separate", arguments->separate,
                       "EPS|auto: move each split vertex copy EPS (model units) into its own fan, "
                       "so the repair survives STL readers that weld by position; auto = for STL "
                       "output, the smallest EPS float32 and a re-read's weld keep apart, reported "
                       "with its size (other formats keep shared vertices: nothing moves); 0 = "
                       "positions exact (an STL reader then welds the copies again); an STL output "
                       "is read back and what a reader gets is reported")
          ->capture_default_str()
          ->check(distance_or_auto());
  add_fill_holes_option(*command, arguments->fill_holes);
  command->add_flag(
      "--print", arguments->print,
      "the slicer route: gap closing as wide as PrusaSlicer's load-time repair (1e-4 x the "
      "bounding box diagonal, unless --weld), duplicate faces removed, holes of up to 32 edges "
      "filled (unless --fill-holes), OUT written as 3MF; the summary ends with what is still "
      "open and why");
  command->add_flag("--self-intersections", arguments->self_intersections,
                    "also find the faces of the result that cross or overlap each other (as "
                    "`check --self-intersections`; repair does not resolve them): in the summary "
                    "and the report's self_intersections");
  command->add_option("--before-after", arguments->before_after,
                      "also draw the input and the result side by side into this PNG (as "
                      "`snapshot` draws them, same framing; with --self-intersections the faces "
                      "that cross are violet)");
  add_view_options(*command, arguments->view, arguments->focus, arguments->up);
  command->add_flag("--progress", arguments->progress,
                    "show the stage and a progress bar on stderr even when it is not a terminal "
                    "(on a terminal it shows anyway once the work takes over a second)");
  command->callback([arguments, separate, command, &exit_code] {
    arguments->separate_given = separate->count() > 0;
    arguments->weld_given = command->count("--weld") > 0;
    arguments->fill_holes_given = command->count("--fill-holes") > 0;
    exit_code = run_repair(*arguments);
  });
}

}  // namespace meshbridge::cli
