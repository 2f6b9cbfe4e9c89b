// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/batch_warnings.h"

#include "meshbridge/counted.h"
#include "meshbridge/io.h"

#include <string>

namespace meshbridge {

namespace {

//! Harmless warnings: what the line contains -> the kind printed once for the whole batch.
struct Harmless {
  const char* contains;
  const char* kind;
};
constexpr Harmless kHarmless[] = {
    {"ASCII STL solid names", "ASCII STL solid names not written (MeshBridge reads past them)"},
    {"STL facet normals against the winding",
     "STL facet normals against the winding of their corners (written ones follow the winding)"},
    {"PLY comment and obj_info lines",
     "PLY comment and obj_info lines not written (MeshBridge reads past them)"},
    {"rounded to 32-bit floats",
     "vertex positions rounded to 32-bit floats (STL and 3MF hold no more)"},
    {"as lib3mf wrote them",
     "vertex positions moved by lib3mf's rounding (3MF text, at most 6 decimals)"},
};

}  // namespace

std::string batch_warning_lines(const FileJobResult& result, const FileJob& job) {
  std::string lines = result.reading.empty() ? "" : result.reading + "\n";
  for (const std::string& what : result.written.left_out)
    lines += "output " + job.output_name + ": " + what + "\n";
  if (result.reread) {
    const std::size_t edges = result.reread->singular_edges.size();
    const std::size_t vertices = result.reread->num_singular_vertices();
    if (edges + vertices > 0 && mesh_format(job.output_name) != MeshFormat::stl) {
      lines += "output " + job.output_name + ": holds triangles only: cut into triangles, the " +
               "repaired polygons have " + counted(edges, "singular edge") + " and " +
               counted(vertices, "singular vertex") +
               " (polygons split at an edge's midpoint on both sides of one sheet share a "
               "diagonal)\n";
    } else if (edges + vertices > 0) {
      lines += "output " + job.output_name +
               ": STL has no shared vertices; reading it welds the split vertex copies again "
               "and re-creates " +
               counted(edges, "singular edge") + " and " + counted(vertices, "singular vertex") +
               " (positions were kept exact)\n";
    }
  }
  return lines;
}

std::string harmless_warning_kind(const std::string& line) {
  for (const Harmless& h : kHarmless) {
    if (line.find(h.contains) != std::string::npos)
      return h.kind;
  }
  return "";
}

}  // namespace meshbridge
