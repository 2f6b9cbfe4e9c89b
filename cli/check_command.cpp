// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"
#include "paths.h"
#include "printer_options.h"
#include "progress.h"
#include "validators.h"

#include "meshbridge/counted.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/read_accounting.h"
#include "meshbridge/report_json.h"
#include "meshbridge/self_intersections.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace meshbridge::cli {

namespace {

struct CheckArguments {
  std::string file;
  bool json = false;
  bool elements = false;
  bool progress = false;
  bool self_intersections = false;  //!< also find the faces that cross (find_self_intersections)
  std::string weld = "auto";  //!< tolerance of the gap closing repair would do ("auto", 0 = off)
  AmbiguousNesting nested = AmbiguousNesting::material;  //!< as repair's --nested-shells
};

int run_check(const CheckArguments& arguments) {
  const std::string& path = arguments.file;
  check_readable_file(path);
  CloseGapsOptions weld = parse_weld(arguments.weld);
  ReadInfo info;
  MeshAttributes attributes;  // for the faults among what the reader reads past
  DefectReport report;
  CloseGapsReport gaps;
  OrientationPreview orientation;  // what repair would reverse, on a watertight file
  RepairPreview preview;           // what repair with the default options would change
  std::string weld_hint;           // what a wider weld would close, when boundary edges are left
  std::unique_ptr<SelfIntersectionReport> crossings;  // with --self-intersections
  {
    ProgressDisplay progress(path, progress_wanted(arguments.progress), progress_wanted(false),
                             check_plan());
    progress.stage(Stage::read, 0);
    const Soup soup = read_soup(path, &info, &attributes);
    weld.float_coordinates = info.float_coordinates;
    progress.stage(Stage::detect, 0);
    // The file as read, and what repair would do: on a watertight file from detection, on any
    // other by repairing in memory (gap closing as repair keeps or refuses it).
    RepairOptions repair_options;
    repair_options.close_gaps = weld;
    repair_options.nested_shells = arguments.nested;
    SoupCheck checked = check_soup(soup, repair_options);
    report = std::move(checked.report);
    orientation = checked.orientation;
    preview = std::move(checked.preview);
    count_records_without_corners(info, report);  // face records with no corner: set aside too
    gaps = preview.ran_repair ? preview.report.gaps : preview_close_gaps(soup, weld, &report);
    if (!arguments.json)
      weld_hint = wider_weld_hint(soup, weld, gaps, report);
    if (arguments.self_intersections)
      crossings = std::make_unique<SelfIntersectionReport>(find_self_intersections(soup));
  }
  warn_about_reader(path, info);
  warn_about_file_faults(path, attributes);
  if (arguments.json) {
    ReportJsonOptions json;
    json.elements = arguments.elements;
    std::cout << check_report_json(path, report, &info, json, &gaps, crossings.get(), &orientation,
                                   &preview)
              << "\n";
  } else {
    std::cout << path << "\n"
              << "  read: " << describe_reading(info) << "\n";
    if (!attributes.length_unit.empty() && attributes.length_unit != "millimeter") {
      std::cout << "  unit: " << attributes.length_unit
                << " (the 3MF model's; coordinates as written, in that unit)\n";
    }
    const std::string others = describe_face_objects(attributes.face_objects);
    if (!others.empty()) {
      std::cout << "  3MF objects that are not the printed model: " << others
                << " (kept apart in a 3MF output)\n";
    }
    std::cout << to_text(report);
    if (crossings)
      std::cout << to_text(*crossings, arguments.elements ? crossings->face_pairs.size() : 10);
    std::cout << gaps_line(gaps, true) << weld_hint;
    if (orientation.faces_flipped != 0) {
      std::cout << "orientation: repair would reverse "
                << counted(orientation.faces_flipped, "face")
                << " (closed shells face outward, cavities toward the void)\n";
    }
    std::cout << to_text(preview);
    if (orientation.ambiguous_nested_shells != 0) {
      std::cout << "nested shells: " << orientation.ambiguous_nested_shells
                << " wound like the shell around them (an insert, or a cavity wound the wrong "
                << (arguments.nested == AmbiguousNesting::cavity
                        ? "way): repair reverses them into voids (--nested-shells cavity)\n"
                        : "way): repair keeps them as written (--nested-shells cavity: voids)\n");
    }
    if (report.has_defects() || (crossings && crossings->has_self_intersections()))
      std::cout << "(`meshbridge explain` tells what these terms mean)\n";
  }
  // check exits 0 exactly when repair (default options, check's --weld and --nested-shells)
  // would change nothing (DESIGN 8a): an open sheet it leaves as it is passes, a watertight file
  // it would turn inside out does not. Self-intersections, when looked for, are defects too.
  // Records the reader did not keep as one simple polygon (split, set aside, dangling edges,
  // trailing bytes...) are changes too: the written file holds the surface only.
  const bool crossing = crossings && crossings->has_self_intersections();
  return preview.changes || info.changed_anything() || crossing ? kDefectsFound : kOk;
}

//! run_check; with --json, an error is also a JSON object on stdout (for scripts that parse it),
//! then passed on to main, which names it on stderr and exits 2.
int run_check_or_report_error(const CheckArguments& arguments) {
  if (!arguments.json)
    return run_check(arguments);
  try {
    return run_check(arguments);
  } catch (const std::bad_alloc&) {
    std::cout << check_failed_json(arguments.file, "out of memory") << "\n";
    throw;
  } catch (const std::exception& error) {
    std::cout << check_failed_json(arguments.file, error.what()) << "\n";
    throw;
  }
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<CheckArguments>();
  CLI::App* command = app.add_subcommand(
      "check",
      "Report singular edges and vertices, boundaries and other defects of FILE, and what\n"
      "repair would change. Exit 0 = repair would change nothing, 1 = it would (or, with\n"
      "--self-intersections, faces cross), 2 = error.");
  command->add_option("FILE", arguments->file, "mesh to check (.obj, .off, .ply, .stl, .3mf)")
      ->required();
  command->add_flag(
      "--json", arguments->json,
      "print the report as JSON instead of text (docs/report-schema.md); a file that "
      "cannot be checked prints {..., \"status\": \"failed\", \"reason\": MESSAGE} and exits 2");
  command->add_flag("--elements", arguments->elements,
                    "with --json: also list the defective elements (vertex indices, edges); "
                    "default counts only. With --self-intersections: every crossing face pair "
                    "(text and JSON)");
  command->add_flag("--self-intersections", arguments->self_intersections,
                    "also find the faces that cross or overlap each other (exact predicates; "
                    "touching at a shared vertex or edge is not crossing): face pairs, faces, "
                    "and pairs of shells that cross. Off by default: it costs about as much as "
                    "the rest of check (README, 'Self-intersections')");
  command
      ->add_option("--weld", arguments->weld,
                   "TOL|auto: also say what repair's gap closing would weld and close with this "
                   "tolerance (as in repair; 0 = off)")
      ->capture_default_str()
      ->check(distance_or_auto());
  add_nested_shells_option(*command, arguments->nested);
  command->add_flag("--progress", arguments->progress,
                    "show the stage and a progress bar on stderr even when it is not a terminal "
                    "(on a terminal it shows anyway once the work takes over a second)");
  command->callback([arguments, &exit_code] { exit_code = run_check_or_report_error(*arguments); });
}

}  // namespace meshbridge::cli
