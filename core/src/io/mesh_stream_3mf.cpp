// SPDX-License-Identifier: GPL-3.0-or-later
// Why this reads what read_meshes_xml() reads: that route cuts a list from "<vertices>" (or
// "<triangles>") to the first "</vertices>" after it, and scans the text between. The scan's
// narrow form holds no "</", so where a list of that form ends the scan stops at the same end
// tag; this route takes a list only when the scan read all of it up to that tag, cut as
// find_cuts() cuts it, and the structure (all outside the lists) is the same text.
#include "io/mesh_stream_3mf.h"

#include "io/inflate_chunks.h"
#include "io/mesh_scan_3mf.h"

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

namespace {

// A list as it was scanned: of triangles (checked against `vertex_count` vertices, those of the
// vertex list before it) or of vertices.
struct ScannedList {
  bool triangles = false;
  std::size_t vertex_count = 0;
  MeshXml mesh;  // positions, or corners
};

// Reads the part chunk by chunk: the text outside the lists into `structure`, each list
// scanned into `lists`.
class ModelReader {
 public:
  explicit ModelReader(std::uint64_t part_size) : part_size_(part_size) {}

  // The next chunk (`size` bytes at `data`, kChunkHeadroom writable bytes before it).
  bool read(char* data, std::size_t size, bool last) {
    // The unread end of the previous chunk (an element or a tag the border cut), in front.
    char* head = data - carry_.size();
    std::memcpy(head, carry_.data(), carry_.size());
    const char* p = head;
    carry_.clear();
    data_offset_ = offset_;
    offset_ += size;
    const char* end = data + size;
    while (p < end) {
      if (!inside_) {
        const char* tag = static_cast<const char*>(std::memchr(p, '<', std::size_t(end - p)));
        if (tag == nullptr) {
          structure.append(p, end);
          break;
        }
        structure.append(p, tag);
        if (end - tag < 11 && !last)
          return keep(tag, end);
        const std::string_view rest(tag, std::min<std::size_t>(11, std::size_t(end - tag)));
        const bool vertices = rest.substr(0, 10) == "<vertices>";
        if (!vertices && rest != "<triangles>") {
          structure.push_back('<');
          p = tag + 1;
          continue;
        }
        landed.push_back(structure.size());
        structure.append(tag, vertices ? 10 : 11);
        p = tag + (vertices ? 10 : 11);
        begin_list(!vertices, data_offset_ + std::uint64_t(std::max<std::ptrdiff_t>(0, p - data)));
      } else {
        ScannedList& list = lists.back();
        const char* stop = list.triangles
                               ? scan_triangles_until(p, end, list.vertex_count, list.mesh.corners)
                               : scan_vertices_until(p, end, list.mesh.positions);
        if (stop == end)
          break;
        const std::string_view close = list.triangles ? "</triangles>" : "</vertices>";
        if (std::size_t(end - stop) >= close.size() &&
            std::string_view(stop, close.size()) == close) {
          inside_ = false;  // the end tag is the structure's
          p = stop;
          continue;
        }
        if (last)
          return false;  // not of the narrow form (or no end tag): the part is read whole
        return keep(stop, end);
      }
    }
    return !last || !inside_;
  }

  std::string structure;
  std::vector<std::size_t> landed;  // by list: where its start tag is in `structure`
  std::vector<ScannedList> lists;

 private:
  // Keeps [from, end) for the next chunk, if it fits in front of it.
  bool keep(const char* from, const char* end) {
    if (std::size_t(end - from) > kChunkHeadroom)
      return false;  // not an element the border cut: one the scan does not read
    carry_.assign(from, end);
    return true;
  }

  // A list begins `at` bytes into the part.
  void begin_list(bool triangles, std::uint64_t at) {
    inside_ = true;
    ScannedList list;
    list.triangles = triangles;
    if (triangles) {
      for (auto l = lists.rbegin(); l != lists.rend(); ++l) {
        if (!l->triangles) {
          list.vertex_count = l->mesh.positions.size();
          break;
        }
      }
    }
    // Room for as many elements as the rest of the part can hold (<vertex x="0" y="0" z="0"/>:
    // 27 bytes; a triangle's: 32): address space only, touched as far as it is filled. The
    // first few lists only: many small ones grow as they fill.
    if (lists.size() < 8) {
      const std::uint64_t rest = part_size_ - std::min<std::uint64_t>(part_size_, at);
      if (triangles)
        list.mesh.corners.reserve(std::size_t(3 * (rest / 32 + 1)));
      else
        list.mesh.positions.reserve(std::size_t(rest / 27 + 1));
    }
    lists.push_back(std::move(list));
  }

  std::uint64_t part_size_;
  std::uint64_t offset_ = 0;       // bytes of the part in the chunks read so far
  std::uint64_t data_offset_ = 0;  // where the chunk being read begins in the part
  std::string carry_;
  bool inside_ = false;  // in a list's content
};

}  // namespace

bool read_meshes_streamed(const unsigned char* compressed, std::size_t size,
                          std::uint64_t inflated_size, std::uint32_t crc,
                          std::map<std::uint32_t, MeshXml>& meshes, std::string& stripped) {
  meshes.clear();
  if (!can_inflate_in_chunks())
    return false;
  ModelReader reader(inflated_size);
  if (!inflate_in_chunks(compressed, size, inflated_size, crc,
                         [&](char* data, std::size_t bytes, bool last) {
                           return reader.read(data, bytes, last);
                         })) {
    return false;
  }
  // Every list must be one of a mesh read here, its triangles checked against its own vertices;
  // else the part is read whole.
  std::string structure = reader.structure;  // parsed in place; the copy goes to lib3mf
  std::vector<bool> taken;
  bool whole = true;
  const bool read = read_structure(
      structure, reader.landed,
      [&](std::size_t v, std::size_t t, const std::vector<std::string>&, MeshXml& mesh) {
        ScannedList& vertices = reader.lists[v];
        ScannedList& triangles = reader.lists[t];
        if (vertices.triangles || !triangles.triangles ||
            triangles.vertex_count != vertices.mesh.positions.size()) {
          whole = false;
          return ListOutcome::left_for_lib3mf;
        }
        mesh.positions.swap(vertices.mesh.positions);
        mesh.corners.swap(triangles.mesh.corners);
        return ListOutcome::read;
      },
      meshes, taken);
  for (const bool t : taken)
    whole = whole && t;
  if (!read || !whole) {
    meshes.clear();
    return false;
  }
  stripped = std::move(reader.structure);
  return true;
}

}  // namespace meshbridge::detail
