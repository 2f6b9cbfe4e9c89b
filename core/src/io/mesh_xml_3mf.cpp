// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/mesh_xml_3mf.h"

#include "io/package_3mf.h"

#include <pugixml.hpp>

#include <charconv>
#include <cmath>
#include <cstring>

namespace meshbridge::detail {

namespace {

// True for the name of an attribute of another namespace ("p:UUID", "slic3rpe:...").
bool is_prefixed(const char* name) {
  return std::strchr(name, ':') != nullptr;
}

// The whole of `text` as a number (std::from_chars: no leading space or '+').
template <class Number>
bool parse(const char* text, Number& value) {
  const char* end = text + std::strlen(text);
  const auto result = std::from_chars(text, end, value);
  return result.ec == std::errc() && result.ptr == end && result.ptr != text;
}

enum class Outcome { read, left_for_lib3mf, refused };

// The vertices and triangles of `mesh` into `out`.
Outcome read_mesh(pugi::xml_node mesh, MeshXml& out) {
  pugi::xml_node vertices, triangles;
  for (pugi::xml_node child : mesh.children()) {
    if (child.type() != pugi::node_element)
      continue;
    if (std::strcmp(child.name(), "vertices") == 0 && !vertices)
      vertices = child;
    else if (std::strcmp(child.name(), "triangles") == 0 && !triangles)
      triangles = child;
    else
      return Outcome::left_for_lib3mf;  // a beam lattice, a second list...
  }
  for (pugi::xml_node vertex : vertices.children()) {
    if (vertex.type() != pugi::node_element)
      continue;
    if (std::strcmp(vertex.name(), "vertex") != 0)
      return Outcome::left_for_lib3mf;
    double xyz[3];
    int given = 0;
    for (pugi::xml_attribute a : vertex.attributes()) {
      const char* name = a.name();
      if (name[0] >= 'x' && name[0] <= 'z' && name[1] == '\0') {
        // As lib3mf reads them: a double, rounded to a float.
        if (!parse(a.value(), xyz[name[0] - 'x']))
          return Outcome::refused;
        given |= 1 << (name[0] - 'x');
      } else if (!is_prefixed(name)) {
        return Outcome::left_for_lib3mf;
      }
    }
    if (given != 7)
      return Outcome::refused;
    for (double c : xyz) {
      const float f = static_cast<float>(c);
      if (!std::isfinite(f) || std::abs(f) > 1e9f)
        return Outcome::refused;
      out.positions.push_back(f);
    }
  }
  const std::size_t vertex_count = out.positions.size() / 3;
  for (pugi::xml_node triangle : triangles.children()) {
    if (triangle.type() != pugi::node_element)
      continue;
    if (std::strcmp(triangle.name(), "triangle") != 0)
      return Outcome::left_for_lib3mf;
    std::uint32_t v[3];
    int given = 0;
    for (pugi::xml_attribute a : triangle.attributes()) {
      const char* name = a.name();
      if (name[0] == 'v' && name[1] >= '1' && name[1] <= '3' && name[2] == '\0') {
        if (!parse(a.value(), v[name[1] - '1']))
          return Outcome::refused;
        given |= 1 << (name[1] - '1');
      } else if (!is_prefixed(name)) {
        return Outcome::left_for_lib3mf;  // pid, p1...: properties lib3mf checks and counts
      }
    }
    if (given != 7 || v[0] >= vertex_count || v[1] >= vertex_count || v[2] >= vertex_count ||
        v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      return Outcome::refused;
    }
    out.corners.insert(out.corners.end(), v, v + 3);
  }
  return Outcome::read;
}

// Appends what pugixml writes to a string.
struct StringWriter : pugi::xml_writer {
  std::string& text;
  explicit StringWriter(std::string& t) : text(t) {}
  void write(const void* data, std::size_t size) override {
    text.append(static_cast<const char*>(data), size);
  }
};

}  // namespace

bool read_meshes_xml(std::vector<char>& xml, std::map<std::uint32_t, MeshXml>& meshes,
                     std::string& stripped) {
  pugi::xml_document document;
  // In place, no conversion: escapes stay as written, and are written back as they were.
  const unsigned options = pugi::parse_minimal | pugi::parse_cdata | pugi::parse_declaration;
  if (xml.empty() ||
      !document.load_buffer_inplace(xml.data(), xml.size() - 1, options, pugi::encoding_utf8)) {
    return false;
  }
  pugi::xml_node model = document.child("model");
  if (!model)
    return false;
  for (pugi::xml_node resources : model.children("resources")) {
    for (pugi::xml_node object : resources.children("object")) {
      pugi::xml_node mesh = object.child("mesh");
      std::uint32_t id = 0;
      if (!mesh || !parse(object.attribute("id").value(), id) || meshes.count(id) != 0)
        continue;  // lib3mf's to read (and to refuse)
      MeshXml read;
      const Outcome outcome = read_mesh(mesh, read);
      if (outcome == Outcome::refused)
        return false;
      if (outcome == Outcome::left_for_lib3mf)
        continue;
      meshes.emplace(id, std::move(read));
      while (mesh.first_child())
        mesh.remove_child(mesh.first_child());
      mesh.append_child("vertices");
      mesh.append_child("triangles");
    }
  }
  StringWriter writer(stripped);
  document.save(writer, "",
                pugi::format_raw | pugi::format_no_escapes | pugi::format_no_declaration);
  return true;
}

std::vector<unsigned char> package_without_meshes(const void* data, std::size_t size,
                                                  std::map<std::uint32_t, MeshXml>& meshes) {
  Package3mf package(data, size);
  std::string root, stripped;
  std::vector<char> xml;
  if (!package.is_open() || (root = package.root_model()).empty() || !package.read(root, xml) ||
      !read_meshes_xml(xml, meshes, stripped) || meshes.empty()) {
    meshes.clear();
    return {};
  }
  xml = std::vector<char>();  // freed before lib3mf's turn
  std::vector<unsigned char> without = package.replaced(root, stripped);
  if (without.empty())
    meshes.clear();
  return without;
}

}  // namespace meshbridge::detail
