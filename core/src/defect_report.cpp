// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/defect_report.h"

#include "json_writer.h"

#include <sstream>

namespace meshbridge {

namespace detail {

JsonObject& JsonObject::string(const char* key, const std::string& value) {
  next(key);
  out_ << '"';
  for (char ch : value) {
    if (ch == '"' || ch == '\\') {
      out_ << '\\' << ch;
    } else if (static_cast<unsigned char>(ch) < 0x20) {
      static const char* hex = "0123456789abcdef";
      out_ << "\\u00" << hex[(ch >> 4) & 0xf] << hex[ch & 0xf];
    } else {
      out_ << ch;
    }
  }
  out_ << '"';
  return *this;
}

JsonObject& JsonObject::indices(const char* key, const std::vector<Index>& values) {
  next(key);
  out_ << '[';
  for (std::size_t i = 0; i < values.size(); ++i)
    out_ << (i ? "," : "") << values[i];
  out_ << ']';
  return *this;
}

JsonObject& JsonObject::pairs(const char* key, const std::vector<VertexPair>& values) {
  next(key);
  out_ << '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    out_ << (i ? "," : "") << '[' << values[i].v0 << ',' << values[i].v1 << ']';
  }
  out_ << ']';
  return *this;
}

}  // namespace detail

bool DefectReport::has_defects() const {
  return !singular_edges.empty() || num_singular_vertices() > 0 || !boundary_edges.empty() ||
         !isolated_vertices.empty() || !degenerate_faces.empty() || !excluded_faces.empty() ||
         !duplicate_faces.empty() || !inconsistent_edges.empty() ||
         num_nonorientable_components > 0;
}

namespace {

template <class T, class Print>
void list(std::ostringstream& out, const char* label, const std::vector<T>& items,
          std::size_t max_listed, Print print) {
  out << "  " << label << ": " << items.size();
  if (!items.empty() && max_listed > 0) {
    out << "  [";
    for (std::size_t i = 0; i < items.size() && i < max_listed; ++i) {
      out << (i ? " " : "");
      print(items[i]);
    }
    if (items.size() > max_listed)
      out << " ...";
    out << "]";
  }
  out << "\n";
}

}  // namespace

std::string to_text(const DefectReport& r, std::size_t max_listed) {
  std::ostringstream out;
  const auto index = [&](Index i) { out << i; };
  const auto pair = [&](const VertexPair& p) { out << p.v0 << "-" << p.v1; };
  out << "vertices " << r.num_vertices << ", faces " << r.num_faces << ", edges " << r.num_edges
      << ", components " << r.num_components << ", Euler characteristic " << r.euler_characteristic
      << ", watertight " << (r.watertight ? "yes" : "no") << "\n";
  list(out, "singular edges", r.singular_edges, max_listed, [&](const SingularEdge& e) {
    out << e.vertices.v0 << "-" << e.vertices.v1 << "(" << e.contenders << ")";
  });
  list(out, "singular vertices on singular edges", r.singular_edge_vertices, max_listed, index);
  list(out, "pinch vertices", r.pinch_vertices, max_listed, index);
  list(out, "boundary edges", r.boundary_edges, max_listed, pair);
  out << "  boundary loops: " << r.num_boundary_loops << "\n";
  list(out, "inconsistently oriented edges", r.inconsistent_edges, max_listed, pair);
  out << "  non-orientable components: " << r.num_nonorientable_components << "\n";
  list(out, "isolated vertices", r.isolated_vertices, max_listed, index);
  list(out, "degenerate faces (repeated vertex)", r.degenerate_faces, max_listed, index);
  list(out, "faces set aside (< 3 distinct vertices)", r.excluded_faces, max_listed, index);
  list(out, "zero-area faces", r.zero_area_faces, max_listed, index);
  list(out, "duplicate faces", r.duplicate_faces, max_listed, index);
  return out.str();
}

std::string to_json(const DefectReport& r) {
  std::ostringstream singular;
  singular << '[';
  for (std::size_t i = 0; i < r.singular_edges.size(); ++i) {
    const SingularEdge& e = r.singular_edges[i];
    singular << (i ? "," : "") << "{\"vertices\":[" << e.vertices.v0 << ',' << e.vertices.v1
             << "],\"contenders\":" << e.contenders << '}';
  }
  singular << ']';
  return detail::JsonObject()
      .number("vertices", r.num_vertices)
      .number("faces", r.num_faces)
      .number("edges", r.num_edges)
      .number("components", r.num_components)
      .number("euler_characteristic", r.euler_characteristic)
      .boolean("watertight", r.watertight)
      .boolean("has_defects", r.has_defects())
      .number("singular_edge_count", r.singular_edges.size())
      .number("singular_vertex_count", r.num_singular_vertices())
      .number("boundary_edge_count", r.boundary_edges.size())
      .number("boundary_loops", r.num_boundary_loops)
      .number("nonorientable_components", r.num_nonorientable_components)
      .raw("singular_edges", singular.str())
      .indices("singular_edge_vertices", r.singular_edge_vertices)
      .indices("pinch_vertices", r.pinch_vertices)
      .pairs("boundary_edges", r.boundary_edges)
      .pairs("inconsistent_edges", r.inconsistent_edges)
      .indices("isolated_vertices", r.isolated_vertices)
      .indices("degenerate_faces", r.degenerate_faces)
      .indices("excluded_faces", r.excluded_faces)
      .indices("zero_area_faces", r.zero_area_faces)
      .indices("duplicate_faces", r.duplicate_faces)
      .str();
}

}  // namespace meshbridge
