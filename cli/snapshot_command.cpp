// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"
#include "meshbridge/counted.h"
#include "paths.h"
#include "pictures.h"
#include "progress.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/self_intersections.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <optional>

namespace meshbridge::cli {

namespace {

struct SnapshotArguments {
  std::string file, out;
  std::string view = "auto";
  std::string focus = "auto";
  std::string up = "z";
  SnapshotOptions options;
  bool progress = false;
  bool self_intersections = false;  //!< also draw the faces that cross, violet
};

int run_snapshot(const SnapshotArguments& arguments) {
  const std::string& path = arguments.file;
  const std::string& out = arguments.out;
  SnapshotOptions options = arguments.options;
  options.view = parse_snapshot_view(arguments.view);
  options.focus = parse_snapshot_focus(arguments.focus);
  options.y_up = arguments.up == "y";
  options.title = file_name_of(path);
  if (!ends_with_png(out))
    throw UsageError(out + ": the snapshot is written as PNG; name it .png");
  check_readable_file(path);
  check_writable_file(out);
  find_pictures_module();  // a missing module is told now, not after reading

  ProgressDisplay progress(path, progress_wanted(arguments.progress), progress_wanted(false),
                           snapshot_plan());
  progress.stage(Stage::read, 0);
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  progress.stage(Stage::detect, 0);
  const DefectReport report = detect_defects(soup);
  std::optional<SelfIntersectionReport> crossings;
  if (arguments.self_intersections)
    crossings = find_self_intersections(soup);

  progress.stage(Stage::write, 0);
  Picture picture;
  picture.soup = &soup;
  picture.report = &report;
  picture.options = options;
  picture.crossings = crossings ? &*crossings : nullptr;
  const PicturesDrawn snapshot = write_pictures_png(out, {picture});
  progress.finish();
  warn_about_reader(path, info);
  if (options.legend && !snapshot.legend_drawn) {
    std::cerr << "meshbridge: warning: text does not render here (no font found); " << out
              << " has no legend\n";
  }
  std::cout << path << " -> " << out << " (" << options.size << "x" << options.size << ", view "
            << (options.view.automatic ? "auto -> " : "") << to_string(snapshot.view)
            << (options.y_up ? ", y up" : "")
            << "): " << counted(report.singular_edges.size(), "singular edge") << ", "
            << counted(report.num_singular_vertices(), "singular vertex") << ", "
            << counted(report.boundary_edges.size(), "boundary edge");
  if (crossings)
    std::cout << ", " << counted(crossings->faces.size(), "self-intersecting face");
  std::cout << "; red pixels " << snapshot.red_pixels << ", green pixels " << snapshot.green_pixels;
  if (crossings)
    std::cout << ", violet pixels " << snapshot.violet_pixels;
  std::cout << "\n";
  const bool crossing = crossings && crossings->has_self_intersections();
  return report.has_defects() || crossing ? kDefectsFound : kOk;
}

}  // namespace

void add_snapshot_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<SnapshotArguments>();
  CLI::App* command = app.add_subcommand(
      "snapshot",
      "Draw FILE with its defects into a PNG (no display needed): the surface shaded grey,\n"
      "boundary edges green, singular edges and vertices red, with --self-intersections the\n"
      "faces that cross violet. Exit codes as check.");
  command->add_option("FILE", arguments->file, "mesh to draw (.obj, .off, .ply, .stl, .3mf)")
      ->required();
  command->add_option("OUT.png", arguments->out, "PNG to write; replaced atomically")->required();
  command->add_option("--size", arguments->options.size, "width and height in pixels")
      ->check(CLI::Range(SnapshotOptions::kMinSize, SnapshotOptions::kMaxSize));
  add_view_options(*command, arguments->view, arguments->focus, arguments->up);
  command->add_flag("--self-intersections", arguments->self_intersections,
                    "also find the faces that cross or overlap each other (as check "
                    "--self-intersections) and draw them violet, MeshLab's colour for them");
  command->add_flag("--progress", arguments->progress,
                    "show the stage and a progress bar on stderr even when it is not a terminal "
                    "(on a terminal it shows anyway once the work takes over a second)");
  command->callback([arguments, &exit_code] { exit_code = run_snapshot(*arguments); });
}

}  // namespace meshbridge::cli
