// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"
#include "commands.h"

#include "meshbridge/bridged_mesh.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/stock_build.h"

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace meshbridge::cli {

namespace {

struct Figures {
  std::size_t vertices, faces, detached, lost, boundary_edges, components;
};

// Faces count file records: a record is kept if some polygon of the mesh comes from it (a split
// one gives several), lost otherwise (set aside, or without any corner in the file).
Figures bridged_figures(const BridgedMesh& bridged, const Soup& soup, const ReadInfo& info) {
  const DefectReport report = detect_defects(bridged.indexed.soup);
  std::vector<char> kept(soup.num_faces(), 0);
  for (Index origin : bridged.indexed.face_origin)
    kept[origin] = 1;
  const auto kept_records = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1));
  return {bridged.mesh.n_vertices(),
          kept_records,
          0,
          soup.num_faces() - kept_records + info.faces_without_corners,
          report.boundary_edges.size(),
          report.num_components};
}

}  // namespace

int compare_command(const std::vector<std::string>& args) {
  const Arguments arguments(args, {"json"}, {});
  arguments.expect_positionals(1, "meshbridge compare FILE [--json]");
  const std::string& path = arguments.positionals()[0];
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  warn_about_reader(path, info);
  const StockBuild stock = build_stock(soup);
  const BridgedMesh bridged = build_bridged_mesh(soup);
  const Figures b = bridged_figures(bridged, soup, info);
  const StockBuildReport& s = stock.report;
  if (arguments.flag("json")) {
    std::cout << "{\"file\":\"" << path << "\",\"stock\":" << to_json(s)
              << ",\"bridged\":{\"vertices\":" << b.vertices << ",\"faces_kept\":" << b.faces
              << ",\"faces_detached\":0,\"faces_lost\":" << b.lost
              << ",\"boundary_edges\":" << b.boundary_edges << ",\"components\":" << b.components
              << ",\"add_face_failures\":" << bridged.add_face_failures << "}}\n";
    return kOk;
  }
  std::cout << path << ": " << soup.num_vertices() << " vertices, " << info.declared_faces
            << " faces in the file\n";
  std::cout << std::left << std::setw(18) << "" << std::right << std::setw(16) << "OpenMesh stock"
            << std::setw(16) << "MeshBridge"
            << "\n";
  const auto row = [](const char* label, std::size_t stock_value, std::size_t bridged_value) {
    std::cout << std::left << std::setw(18) << label << std::right << std::setw(16) << stock_value
              << std::setw(16) << bridged_value << "\n";
  };
  row("vertices", s.vertices_created, b.vertices);
  row("faces kept", s.faces_kept, b.faces);
  row("faces detached", s.faces_detached, b.detached);
  row("faces lost", s.faces_lost + info.faces_without_corners, b.lost);
  row("boundary edges", s.boundary_edges, b.boundary_edges);
  row("components", s.components, b.components);
  return kOk;
}

}  // namespace meshbridge::cli
