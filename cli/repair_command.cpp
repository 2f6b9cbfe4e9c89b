// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"
#include "commands.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/separate_copies.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace meshbridge::cli {

namespace {

bool ends_with_stl(std::string path) {
  for (auto& ch : path)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".stl") == 0;
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_bytes_atomically(path, text);  // unique temporary beside `path`, renamed on success
}

}  // namespace

int repair_command(const std::vector<std::string>& args) {
  const Arguments arguments(args,
                            {"no-orient", "no-stitch", "cut-nonorientable", "remove-duplicates",
                             "remove-degenerate", "remove-isolated", "json"},
                            {"report", "pairing", "separate"});
  arguments.expect_positionals(2, "meshbridge repair IN OUT [options]");
  const std::string& in = arguments.positionals()[0];
  const std::string& out = arguments.positionals()[1];

  RepairOptions options;
  const std::string pairing = arguments.value("pairing", "geometric");
  if (pairing == "geometric") {
    options.pairing = PairingPolicy::geometric;
  } else if (pairing == "combinatorial") {
    options.pairing = PairingPolicy::combinatorial;
  } else {
    throw UsageError("--pairing must be geometric or combinatorial, got '" + pairing + "'");
  }
  options.orient = !arguments.flag("no-orient");
  options.stitch = !arguments.flag("no-stitch");
  options.cut_nonorientable = arguments.flag("cut-nonorientable");
  options.remove_duplicate_faces = arguments.flag("remove-duplicates");
  options.remove_degenerate_faces = arguments.flag("remove-degenerate");
  options.remove_isolated_vertices = arguments.flag("remove-isolated");
  const double separate = arguments.number("separate", 0.0);
  if (separate < 0)
    throw UsageError("--separate expects a distance >= 0");
  if (!is_supported_mesh_file(out)) {
    throw UsageError(out + ": unknown output format (expected .obj, .off, .ply or .stl)");
  }

  ReadInfo info;
  const Soup soup = read_soup(in, &info);
  warn_about_reader(in, info);
  RepairResult result = repair(soup, options);
  std::size_t moved = 0;
  if (separate > 0)
    moved = separate_split_vertices(result.mesh, separate);
  write_mesh(out, result.mesh);
  if (arguments.has("report"))
    write_text_atomically(arguments.value("report"), to_json(result.report) + "\n");

  std::cout << in << " -> " << out << "\n" << to_text(result.report);
  if (separate > 0)
    std::cout << "separated " << moved << " split vertex copies by " << separate << "\n";
  if (ends_with_stl(out) && result.report.vertices_split > 0 && separate == 0) {
    std::cerr << "meshbridge: warning: STL has no shared vertices; a reader that welds by position "
                 "will merge the "
              << result.report.vertices_split
              << " split vertex copies again and re-create the singular vertices. Use "
                 "--separate EPS or another format (OBJ, OFF, PLY).\n";
  }
  return kOk;
}

}  // namespace meshbridge::cli
