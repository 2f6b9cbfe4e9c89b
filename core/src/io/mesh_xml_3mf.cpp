// SPDX-License-Identifier: GPL-3.0-or-later
// The model part is read in two steps. The text between <vertices> and </vertices> and between
// <triangles> and </triangles> is cut out, and pugixml parses the rest (small: the structure,
// build, metadata, materials), which tells which cut is the vertex or triangle list of which
// object's mesh. Each list is then read by the direct scan (mesh_scan_3mf.h) or, where it gives
// up, parsed by pugixml as a run of fragments of about 256 KiB
// (copied, so the part stays as written), one document reused for all, so that the tree of a
// million elements is never held at once (it would take 200 bytes an element, and the page
// faults cost more than the parse). A list of a mesh this reader does not take stays in the
// part, for lib3mf.
#include "io/mesh_xml_3mf.h"

#include "io/inflate_chunks.h"
#include "io/mesh_scan_3mf.h"
#include "io/mesh_stream_3mf.h"
#include "io/package_3mf.h"
#include "parallel_parts.h"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace meshbridge::detail {

namespace {

// True for the name of an attribute of another namespace ("p:UUID", "slic3rpe:...") whose prefix
// is one of `prefixes` (declared around the mesh; lib3mf refuses one that is not declared).
bool is_declared_prefixed(const char* name, const std::vector<std::string>& prefixes) {
  const char* colon = std::strchr(name, ':');
  if (colon == nullptr)
    return false;
  const std::string_view prefix(name, std::size_t(colon - name));
  return prefix == "xml" || std::find(prefixes.begin(), prefixes.end(), prefix) != prefixes.end();
}

// The namespace prefixes declared on `node` and the elements around it ("xmlns:p=...": "p").
std::vector<std::string> declared_prefixes(pugi::xml_node node) {
  std::vector<std::string> prefixes;
  for (; node; node = node.parent()) {
    for (pugi::xml_attribute a : node.attributes()) {
      if (std::strncmp(a.name(), "xmlns:", 6) == 0)
        prefixes.emplace_back(a.name() + 6);
    }
  }
  return prefixes;
}

// The whole of the NUL-terminated `text` as a number (std::from_chars: no space, no '+');
// `end` bounds the search (the end of the buffer `text` is in).
template <class Number>
bool parse(const char* text, const char* end, Number& value) {
  const auto result = std::from_chars(text, end, value);
  return result.ec == std::errc() && result.ptr != text && *result.ptr == '\0';
}

using Outcome = ListOutcome;

// A list's content in the model part: [begin, end), after its start tag.
struct Cut {
  std::size_t tag = 0;  // offset of the '<' of its start tag
  std::size_t begin = 0, end = 0;
  bool taken = false;  // a list of a mesh read here (else put back for lib3mf)
};

// Every cut: the lists "<vertices>...</vertices>" and "<triangles>...</triangles>", in order.
// Their ends are found by the byte 's', which no vertex or triangle of the core specification
// holds: the scan passes over a list at memchr's speed, not stopping at each '<'.
void find_cuts(std::string_view text, std::vector<Cut>& cuts) {
  std::size_t at = 0;
  while ((at = text.find('<', at)) != std::string_view::npos) {
    const std::string_view rest = text.substr(at);
    const std::string_view name = rest.substr(0, 10) == "<vertices>"    ? "vertices"
                                  : rest.substr(0, 11) == "<triangles>" ? "triangles"
                                                                        : "";
    if (name.empty()) {
      ++at;
      continue;
    }
    const std::size_t begin = at + name.size() + 2;
    std::size_t s = begin;
    // "</vertices>": its 's' is 2 bytes before its end.
    while ((s = text.find('s', s)) != std::string_view::npos) {
      const std::size_t close = s + 2 - (name.size() + 3);
      if (s + 2 <= text.size() && s + 2 >= begin + name.size() + 3 &&
          text.substr(close, 2) == "</" && text.substr(close + 2, name.size()) == name &&
          text[s + 1] == '>') {
        break;
      }
      ++s;
    }
    if (s == std::string_view::npos)
      return;  // no end: pugixml refuses the structure
    cuts.push_back({at, begin, s + 2 - (name.size() + 3), false});
    at = s + 2;
  }
}

// Reused by every fragment of every list: the copy of the fragment pugixml parses in place (the
// model part stays as written, for lib3mf where a list is left to it) and its document.
struct Fragments {
  const std::vector<std::string>& prefixes;  // declared around the mesh
  std::vector<char> text;
  pugi::xml_document document;
};

// Calls element(node, end of the fragment's text) for every element of the list [begin, end),
// parsed in fragments; an element of another name than `name`, or text, leaves the list to
// lib3mf.
template <class Element>
Outcome parse_list(const char* begin, const char* end, const char* name, Fragments& fragments,
                   Element element) {
  constexpr std::size_t kFragment = std::size_t(1) << 18;
  const unsigned options = pugi::parse_minimal | pugi::parse_fragment;
  while (begin < end) {
    // Fragments end before a '<' (never inside a tag: '<' is not allowed in attribute values).
    const char* stop = end;
    if (std::size_t(end - begin) > kFragment) {
      stop = static_cast<const char*>(std::memchr(begin + kFragment, '<', end - begin - kFragment));
      if (stop == nullptr)
        stop = end;
    }
    fragments.text.assign(begin, stop);
    fragments.text.push_back('\0');
    if (!fragments.document.load_buffer_inplace(fragments.text.data(), fragments.text.size() - 1,
                                                options, pugi::encoding_utf8)) {
      return Outcome::refused;  // lib3mf names the fault
    }
    const char* text_end = fragments.text.data() + fragments.text.size();
    for (pugi::xml_node node : fragments.document.children()) {
      if (node.type() != pugi::node_element || std::strcmp(node.name(), name) != 0)
        return Outcome::left_for_lib3mf;
      const Outcome outcome = element(node, text_end);
      if (outcome != Outcome::read)
        return outcome;
    }
    begin = stop;
  }
  return Outcome::read;
}

// The vertex list [begin, end) into `out`.
Outcome read_vertices(const char* begin, const char* end, Fragments& fragments, MeshXml& out) {
  return parse_list(begin, end, "vertex", fragments, [&](pugi::xml_node vertex, const char* stop) {
    double xyz[3];
    int given = 0;
    for (pugi::xml_attribute a : vertex.attributes()) {
      const char* name = a.name();
      if (name[0] >= 'x' && name[0] <= 'z' && name[1] == '\0') {
        // As lib3mf reads them: a double, rounded to a float.
        if (!parse(a.value(), stop, xyz[name[0] - 'x']))
          return Outcome::refused;
        given |= 1 << (name[0] - 'x');
      } else if (!is_declared_prefixed(name, fragments.prefixes)) {
        return Outcome::left_for_lib3mf;
      }
    }
    if (given != 7)
      return Outcome::refused;
    float f[3];
    for (int k = 0; k < 3; ++k) {
      f[k] = static_cast<float>(xyz[k]);
      if (!std::isfinite(f[k]) || std::abs(f[k]) > 1e9f)
        return Outcome::refused;  // lib3mf's limit
    }
    out.positions.emplace_back(f[0], f[1], f[2]);
    return Outcome::read;
  });
}

// The triangle list [begin, end) into `out`, its corners checked against the mesh's
// `vertex_count` vertices.
Outcome read_triangles(const char* begin, const char* end, Fragments& fragments,
                       std::size_t vertex_count, MeshXml& out) {
  return parse_list(
      begin, end, "triangle", fragments, [&](pugi::xml_node triangle, const char* stop) {
        std::uint32_t v[3];
        int given = 0;
        for (pugi::xml_attribute a : triangle.attributes()) {
          const char* name = a.name();
          if (name[0] == 'v' && name[1] >= '1' && name[1] <= '3' && name[2] == '\0') {
            if (!parse(a.value(), stop, v[name[1] - '1']))
              return Outcome::refused;
            given |= 1 << (name[1] - '1');
          } else if (!is_declared_prefixed(name, fragments.prefixes)) {
            return Outcome::left_for_lib3mf;  // pid, p1...: properties lib3mf checks and counts
          }
        }
        if (given != 7 || v[0] >= vertex_count || v[1] >= vertex_count || v[2] >= vertex_count ||
            v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
          return Outcome::refused;
        }
        out.corners.insert(out.corners.end(), v, v + 3);
        return Outcome::read;
      });
}

// The list [begin, end) (of triangles, else of vertices) read into `out`: in parts side by side
// (worker_threads(), parts of at least 4 MiB, each cut before a '<'), appended in order.
Outcome read_list(bool triangles, const char* begin, const char* end, std::size_t vertex_count,
                  const std::vector<std::string>& prefixes, MeshXml& out) {
  constexpr std::size_t kPart = std::size_t(1) << 22;
  const unsigned n = static_cast<unsigned>(
      std::max<std::size_t>(1, std::min<std::size_t>(worker_threads(), (end - begin) / kPart)));
  std::vector<const char*> bounds{begin};
  for (unsigned k = 1; k < n; ++k) {
    const char* at = begin + (end - begin) / n * k;
    const char* tag = static_cast<const char*>(std::memchr(at, '<', end - at));
    bounds.push_back(std::max(tag != nullptr ? tag : end, bounds.back()));
  }
  bounds.push_back(end);
  std::vector<MeshXml> parts(n);
  std::vector<Outcome> outcomes(n, Outcome::read);
  const char* route = std::getenv("MESHBRIDGE_3MF_MESHES");
  const bool scan = route == nullptr || std::strcmp(route, "pugixml") != 0;
  run_parts(n, [&](unsigned k) {
    Fragments fragments{prefixes, {}, {}};
    // Room for as many elements as the shortest can fill (<vertex x="0" y="0" z="0"/>: 27
    // bytes; a triangle's: 32): address space only, never touched beyond what is read, so no
    // vector grows by copying.
    const std::size_t bytes = std::size_t(bounds[k + 1] - bounds[k]);
    // The direct scan first (mesh_scan_3mf.h); where it gives up, pugixml decides.
    if (triangles) {
      parts[k].corners.reserve(3 * (bytes / 32 + 1));
      if (!scan || !scan_triangles(bounds[k], bounds[k + 1], vertex_count, parts[k].corners))
        outcomes[k] = read_triangles(bounds[k], bounds[k + 1], fragments, vertex_count, parts[k]);
    } else {
      parts[k].positions.reserve(bytes / 27 + 1);
      if (!scan || !scan_vertices(bounds[k], bounds[k + 1], parts[k].positions))
        outcomes[k] = read_vertices(bounds[k], bounds[k + 1], fragments, parts[k]);
    }
  });
  for (const Outcome o : {Outcome::refused, Outcome::left_for_lib3mf}) {
    if (std::find(outcomes.begin(), outcomes.end(), o) != outcomes.end())
      return o;
  }
  std::vector<Point>& positions = out.positions;
  std::vector<std::uint32_t>& corners = out.corners;
  if (n == 1) {
    (triangles ? corners.swap(parts[0].corners) : positions.swap(parts[0].positions));
    return Outcome::read;
  }
  std::size_t total = 0;
  for (const MeshXml& part : parts)
    total += triangles ? part.corners.size() : part.positions.size();
  (triangles ? corners.reserve(total) : positions.reserve(total));
  for (MeshXml& part : parts) {
    if (triangles)
      corners.insert(corners.end(), part.corners.begin(), part.corners.end());
    else
      positions.insert(positions.end(), part.positions.begin(), part.positions.end());
    part = MeshXml();
  }
  return Outcome::read;
}

// `text` without the contents of the cuts taken (all of them with `all`), and where each cut's
// start tag lands in it (`landed`, by cut).
std::string without_cuts(std::string_view text, const std::vector<Cut>& cuts, bool all,
                         std::vector<std::size_t>* landed) {
  std::string out;
  std::size_t from = 0;
  for (const Cut& cut : cuts) {
    if (landed != nullptr)
      landed->push_back(out.size() + (cut.tag - from));
    if (!all && !cut.taken)
      continue;
    out.append(text.substr(from, cut.begin - from));
    from = cut.end;
  }
  out.append(text.substr(from));
  return out;
}

}  // namespace

bool read_structure(std::string& structure, const std::vector<std::size_t>& landed,
                    const ReadMesh& read_mesh, std::map<std::uint32_t, MeshXml>& meshes,
                    std::vector<bool>& taken) {
  const std::size_t cut_count = landed.size();
  taken.assign(cut_count, false);
  pugi::xml_document document;
  // In place, no conversion: only the structure is read here; lib3mf reads it again.
  if (!document.load_buffer_inplace(structure.data(), structure.size(),
                                    pugi::parse_minimal | pugi::parse_cdata, pugi::encoding_utf8)) {
    return false;
  }
  // The cut whose start tag is the one of `list` (cut_count if none).
  const auto cut_of = [&](pugi::xml_node list) {
    const std::size_t tag = static_cast<std::size_t>(list.name() - structure.data()) - 1;
    const auto at = std::lower_bound(landed.begin(), landed.end(), tag);
    return at != landed.end() && *at == tag ? std::size_t(at - landed.begin()) : cut_count;
  };
  for (pugi::xml_node resources : document.child("model").children("resources")) {
    for (pugi::xml_node object : resources.children("object")) {
      pugi::xml_node mesh = object.child("mesh");
      std::uint32_t id = 0;
      const char* id_text = object.attribute("id").value();
      if (!mesh || !parse(id_text, id_text + std::strlen(id_text), id) || meshes.count(id) != 0)
        continue;  // lib3mf's to read (and to refuse)
      // Its lists, both cut, and nothing else in it.
      std::size_t lists[2] = {cut_count, cut_count};
      bool other = false;
      for (pugi::xml_node child : mesh.children()) {
        const bool vertices = std::strcmp(child.name(), "vertices") == 0;
        const bool triangles = std::strcmp(child.name(), "triangles") == 0;
        const std::size_t c = vertices || triangles ? cut_of(child) : cut_count;
        if (c == cut_count || lists[triangles ? 1 : 0] != cut_count || child.first_child())
          other = true;
        else
          lists[triangles ? 1 : 0] = c;
      }
      if (other || lists[0] == cut_count || lists[1] == cut_count)
        continue;
      MeshXml read;
      const ListOutcome outcome = read_mesh(lists[0], lists[1], declared_prefixes(mesh), read);
      if (outcome == ListOutcome::refused)
        return false;
      if (outcome == ListOutcome::left_for_lib3mf)
        continue;
      taken[lists[0]] = taken[lists[1]] = true;
      meshes.emplace(id, std::move(read));
    }
  }
  return true;
}

bool read_meshes_xml(std::string_view text, std::map<std::uint32_t, MeshXml>& meshes,
                     std::string& stripped) {
  std::vector<Cut> cuts;
  find_cuts(text, cuts);
  // The structure: the model part without any list.
  std::vector<std::size_t> landed;
  std::string structure = without_cuts(text, cuts, true, &landed);
  std::vector<bool> taken;
  const bool read = read_structure(
      structure, landed,
      [&](std::size_t v, std::size_t t, const std::vector<std::string>& prefixes, MeshXml& mesh) {
        const Cut& vertices = cuts[v];
        const Cut& triangles = cuts[t];
        ListOutcome outcome = read_list(false, text.data() + vertices.begin,
                                        text.data() + vertices.end, 0, prefixes, mesh);
        if (outcome == ListOutcome::read) {
          outcome = read_list(true, text.data() + triangles.begin, text.data() + triangles.end,
                              mesh.positions.size(), prefixes, mesh);
        }
        return outcome;
      },
      meshes, taken);
  if (!read)
    return false;
  for (std::size_t c = 0; c < cuts.size(); ++c)
    cuts[c].taken = taken[c];
  stripped = without_cuts(text, cuts, false, nullptr);
  return true;
}

namespace {

std::vector<unsigned char> package_without_meshes_or_throw(
    const void* data, std::size_t size, std::map<std::uint32_t, MeshXml>& meshes) {
  Package3mf package(data, size);
  std::string root, stripped;
  if (!package.is_open() || (root = package.root_model()).empty())
    return {};
  // Read while it is inflated (mesh_stream_3mf.h), else inflated whole and read: the same
  // meshes. MESHBRIDGE_3MF_MESHES=whole (or pugixml) reads it whole.
  const char* route = std::getenv("MESHBRIDGE_3MF_MESHES");
  bool read = false;
  if (can_inflate_in_chunks() && (route == nullptr || (std::strcmp(route, "whole") != 0 &&
                                                       std::strcmp(route, "pugixml") != 0))) {
    // Inflated from the package as it is in memory (a copy of the 14 MB deflated part of a
    // 1M-triangle 3MF took 7 % of the read), else from a copy libzip reads out.
    PartStat part;
    PartBytes copy;
    const unsigned char* compressed = package.deflated_in_place(root, part);
    if (compressed == nullptr && package.read_deflated(root, part, copy))
      compressed = reinterpret_cast<const unsigned char*>(copy.data.get());
    read = compressed != nullptr && read_meshes_streamed(compressed, part.compressed_size,
                                                         part.size, part.crc, meshes, stripped);
  }
  if (!read) {
    meshes.clear();
    PartBytes xml;
    read = package.read(root, xml) && read_meshes_xml(xml.view(), meshes, stripped);
  }  // the part freed before lib3mf's turn
  if (!read || meshes.empty()) {
    meshes.clear();
    return {};
  }
  std::vector<unsigned char> without = package.replaced(root, stripped);
  if (without.empty())
    meshes.clear();
  return without;
}

}  // namespace

std::vector<unsigned char> package_without_meshes(const void* data, std::size_t size,
                                                  std::map<std::uint32_t, MeshXml>& meshes) {
  try {
    return package_without_meshes_or_throw(data, size, meshes);
  } catch (const std::exception&) {  // out of memory: lib3mf's turn (it names what it cannot do)
    meshes.clear();
    return {};
  }
}

}  // namespace meshbridge::detail
