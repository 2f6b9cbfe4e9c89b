// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

#include "paths.h"

#include "meshbridge/bridged_mesh.h"
#include "meshbridge/counted.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/report_json.h"
#include "meshbridge/stock_build.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>

namespace meshbridge::cli {

namespace {

struct CompareArguments {
  std::string file;
  bool json = false;
};

// Faces count file records: a record is kept if some polygon of the mesh comes from it (a split
// one gives several), lost otherwise (set aside, or without any corner in the file).
BuildFigures bridged_figures(const BridgedMesh& bridged, const Soup& soup, const ReadInfo& info) {
  const DefectReport report = detect_defects(bridged.indexed.soup);
  std::vector<char> kept(soup.num_faces(), 0);
  for (Index origin : bridged.indexed.face_origin)
    kept[origin] = 1;
  const auto kept_records = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1));
  BuildFigures figures;
  figures.vertices = bridged.mesh.n_vertices();
  figures.faces_kept = kept_records;
  figures.faces_lost = soup.num_faces() - kept_records + info.faces_without_corners;
  figures.boundary_edges = report.boundary_edges.size();
  figures.components = report.num_components;
  return figures;
}

BuildFigures stock_figures(const StockBuildReport& s) {
  BuildFigures figures;
  figures.vertices = s.vertices_created;
  figures.faces_kept = s.faces_kept;
  figures.faces_detached = s.faces_detached;
  figures.faces_lost = s.faces_lost;
  figures.boundary_edges = s.boundary_edges;
  figures.components = s.components;
  return figures;
}

int run_compare(const CompareArguments& arguments) {
  const std::string& path = arguments.file;
  check_readable_file(path);
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  warn_about_reader(path, info);
  const StockBuild stock = build_stock(soup);
  const BridgedMesh bridged = build_bridged_mesh(soup);
  const BuildFigures b = bridged_figures(bridged, soup, info);
  BuildFigures s = stock_figures(stock.report);
  s.faces_lost += info.faces_without_corners;
  if (arguments.json) {
    std::cout << compare_report_json(path, soup.num_vertices(), info.declared_faces, s, b) << "\n";
    return kOk;
  }
  std::cout << path << ": " << counted(soup.num_vertices(), "vertex") << ", "
            << counted(info.declared_faces, "face") << " in the file\n";
  std::cout << std::left << std::setw(18) << "" << std::right << std::setw(16) << "OpenMesh stock"
            << std::setw(16) << "MeshBridge"
            << "\n";
  const auto row = [](const char* label, std::size_t stock_value, std::size_t bridged_value) {
    std::cout << std::left << std::setw(18) << label << std::right << std::setw(16) << stock_value
              << std::setw(16) << bridged_value << "\n";
  };
  row("vertices", s.vertices, b.vertices);
  row("faces kept", s.faces_kept, b.faces_kept);
  row("faces detached", s.faces_detached, b.faces_detached);
  row("faces not loaded", s.faces_lost, b.faces_lost);
  row("boundary edges", s.boundary_edges, b.boundary_edges);
  row("components", s.components, b.components);
  if (b.faces_lost > 0) {
    std::cout << "(MeshBridge sets aside faces with fewer than 3 distinct corners and counts "
                 "them, as the warning above says; OpenMesh's loader drops faces without a "
                 "word)\n";
  }
  return kOk;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<CompareArguments>();
  CLI::App* command = app.add_subcommand(
      "compare", "Show OpenMesh's stock loader next to MeshBridge's bridged build of FILE.");
  command->add_option("FILE", arguments->file, "mesh to load (.obj, .off, .ply, .stl)")->required();
  command->add_flag("--json", arguments->json, "print the figures as JSON instead of a table");
  command->callback([arguments, &exit_code] { exit_code = run_compare(*arguments); });
}

}  // namespace meshbridge::cli
