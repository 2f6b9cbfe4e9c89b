// SPDX-License-Identifier: GPL-3.0-or-later
// The PLY reader: ascii, binary little and big endian, any scalar types; `vertex`, `face`,
// `tristrips` and `edge` elements; every other element and property skipped by its declared
// size. Per-vertex and per-face colours go to MeshAttributes.
#include "io/formats.h"
#include "io/huge_pages.h"
#include "io/ply_ascii_lines.h"
#include "io/ply_binary_blocks.h"
#include "io/ply_header.h"
#include "io/ply_roles.h"
#include "io/ply_sources.h"
#include "parallel_parts.h"

#include "meshbridge/counted.h"
#include "meshbridge/errors.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace meshbridge::detail {

namespace {

using Format = PlyHeader::Format;
using Role = PlyRole;

std::string plural(const PlyElement& e) {
  if (e.name == "vertex")
    return "vertices";
  if (e.name == "face")
    return "faces";
  return "'" + e.name + "' items";
}

class PlyReader {
 public:
  PlyReader(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes)
      : file_(file), info_(info), soup_(soup), attributes_(attributes) {}

  void read() {
    header_ = parse_ply_header(file_.view(), file_.path());
    check_ply_elements(header_, file_.path());
    vertices_ = vertex_count();
    if (attributes_ != nullptr && header_.comments > 0)
      attributes_->not_kept.push_back({"PLY comment and obj_info lines", header_.comments, "line"});
    if (attributes_ != nullptr && header_.unknown_lines > 0) {
      attributes_->not_kept.push_back(
          {"PLY header lines that are neither keywords nor comments, read past (the first, line " +
               std::to_string(header_.first_unknown_line_number) + ": '" +
               header_.first_unknown_line + "')",
           header_.unknown_lines, "line", true});
    }
    const char* body = file_.data() + header_.body;
    if (header_.format == Format::ascii) {
      try {
        AsciiSource source(body, file_.end());
        read_elements(source);
        // A count lower than the values given would drop the rest without a word.
        if (!source.only_space_left()) {
          throw ReadError(where() + "ascii PLY: values follow the last declared element (" +
                          (header_.elements.empty()
                               ? std::string("none")
                               : header_.elements.back().name + " " +
                                     std::to_string(header_.elements.back().count)) +
                          "): a false element count, or text after the mesh");
        }
      } catch (const ReadError&) {
        // Values are read as words; the line where they stop matching the header says more.
        if (const auto line = locate_ascii_ply_mismatch(file_.view(), header_))
          throw ReadError(where() + "ascii PLY: " + *line);
        throw;
      }
    } else {
      BinarySource source(body, file_.end(), header_.format == Format::binary_big_endian);
      read_elements(source);
      // Bytes past the declared elements: padding, or items a false count leaves out.
      info_.trailing_bytes = source.remaining();
    }
    check_finite();
    for (const int of : {0, 1}) {
      if (colors_clamped_[of] > 0) {
        const char* noun = of == 0 ? "vertex" : "face";
        attributes_->not_kept.push_back({std::string("PLY ") + noun +
                                             " colour values outside 0-255 (integers) or 0-1 "
                                             "(reals) or not finite, clamped to the range",
                                         colors_clamped_[of], noun, true, true});
      }
    }
    if (attributes_ != nullptr && !attributes_->face_colors.empty())  // strip triangles: none
      pad_missing_colors(attributes_->face_colors, attributes_->face_color_missing,
                         soup_.num_faces());
  }

 private:
  std::string where() const { return file_.path() + ": "; }
  //! The count the header declares for the `vertex` element.
  std::uint64_t vertex_count() const {
    for (const PlyElement& e : header_.elements) {
      if (e.name == "vertex")
        return e.count;
    }
    return 0;
  }
  std::string item(const PlyElement& e, std::uint64_t i) const {
    return "PLY " + e.name + " " + std::to_string(i + 1) + " of " + std::to_string(e.count);
  }
  ReadError unreadable(const PlyElement& e, std::uint64_t i, const PlyProperty& p) const {
    return ReadError(where() + item(e, i) + ": property '" + p.name +
                     "' is missing or unreadable (a truncated file, a false count, or a value "
                     "such as 'nan' or '1.5' where an integer belongs)");
  }

  template <class Source>
  void read_elements(Source& source) {
    for (const PlyElement& e : header_.elements) {
      // A count that no file of this size can hold is refused before anything is reserved.
      const bool ascii = header_.format == Format::ascii;
      const std::size_t least = ascii ? 2 * e.properties.size() - 1 : e.min_size();
      if (e.count > 0 && least > 0 && e.count > source.remaining() / least) {
        const std::size_t fixed = e.fixed_size();
        if (!ascii && fixed > 0) {
          throw ReadError(where() + "binary PLY ends inside element '" + e.name +
                          "': " + std::to_string(e.count) + " items of " + std::to_string(fixed) +
                          " bytes need " + std::to_string(e.count * fixed) + " bytes, " +
                          std::to_string(source.remaining()) +
                          " remain (a truncated file or a false count)");
        }
        throw ReadError(where() + (ascii ? "ascii" : "binary") + " PLY declares " +
                        std::to_string(e.count) + " " + plural(e) + ", more than the " +
                        std::to_string(source.remaining()) +
                        " bytes left can hold (a truncated file or a false count)");
      }
      std::vector<Role> roles;
      for (const PlyProperty& p : e.properties)
        roles.push_back(ply_role(e, p));
      if (attributes_ != nullptr && e.count > 0)
        note_not_kept(e, roles);
      if (e.name == "vertex")
        read_vertices(e, roles, source);
      else
        read_records(e, roles, source);
      if constexpr (std::is_same_v<Source, BinarySource>)  // what is read is not needed again
        file_.release_before(reinterpret_cast<const char*>(source.position()));
    }
  }

  //! The properties of vertices and faces, and the elements, that are read past (an `edge`
  //! element is counted in ReadInfo::dangling_edges instead).
  void note_not_kept(const PlyElement& e, const std::vector<Role>& roles) {
    const bool polygons = e.name == "face" || e.name == "tristrips";
    if (e.name != "vertex" && !polygons) {
      if (e.name != "edge")
        attributes_->not_kept.push_back({"PLY element '" + e.name + "'", e.count, "item"});
      return;
    }
    std::string names;
    std::size_t skipped = 0;
    for (std::size_t k = 0; k < roles.size(); ++k) {
      if (roles[k] != Role::skip)
        continue;
      names += (skipped++ == 0 ? "" : ", ") + e.properties[k].name;
    }
    if (skipped > 0) {
      attributes_->not_kept.push_back(
          {"PLY " + e.name + (skipped == 1 ? " property " : " properties ") + names, e.count,
           e.name == "vertex" ? "vertex"
           : e.name == "face" ? "face"
                              : "strip"});
    }
  }

  bool wants_colors(const std::vector<Role>& roles) const {
    return attributes_ != nullptr && ply_color_channels(roles) != 0;
  }

  template <class Source>
  bool skip_property(const PlyProperty& p, Source& source) {
    if (!p.is_list)
      return source.skip(p.type);
    std::int64_t n = 0;
    if (!source.integer(p.count_type, n) || n < 0)
      return false;
    return source.can_hold(p.type, static_cast<std::uint64_t>(n)) &&
           source.skip(p.type, static_cast<std::uint64_t>(n));
  }

  template <class Source>
  void read_vertices(const PlyElement& e, const std::vector<Role>& roles, Source& source) {
    const std::size_t n = static_cast<std::size_t>(e.count);
    reserve_huge(soup_.positions, n);
    soup_.positions.resize(n);
    info_.declared_vertices = n;
    const bool colors = wants_colors(roles);
    if (colors) {
      attributes_->vertex_colors.resize(n);
      attributes_->vertex_color_channels = ply_color_channels(roles);
    }
    for (std::size_t k = 0; k < roles.size(); ++k) {
      if (roles[k] == Role::x || roles[k] == Role::y || roles[k] == Role::z) {
        if (e.properties[k].type == PlyScalar::f64 && attributes_ != nullptr)
          attributes_->double_precision = true;
        if (e.properties[k].type != PlyScalar::f64)
          info_.float_coordinates = true;  // float, or integers: float rounding at most
      }
    }
    if constexpr (std::is_same_v<Source, BinarySource>) {
      if (!colors && read_vertices_fast(e, roles, source))
        return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Point& point = soup_.positions[i];
      bool clamped = false;
      for (std::size_t k = 0; k < roles.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        const Role r = roles[k];
        double value = 0;
        if (r == Role::skip || (is_color(r) && !colors)) {
          if (!skip_property(p, source))
            throw unreadable(e, i, p);
          continue;
        }
        if (!source.real(p.type, value))
          throw unreadable(e, i, p);
        if (r == Role::x)
          point[0] = value;
        else if (r == Role::y)
          point[1] = value;
        else if (r == Role::z)
          point[2] = value;
        else
          set_color_channel(attributes_->vertex_colors[i], r, ply_channel(value, p.type));
        clamped = clamped || (is_color(r) && ply_channel_clamps(value, p.type));
      }
      colors_clamped_[0] += clamped;
    }
  }

  //! Binary vertices of fixed size whose x, y, z are all float or all double: one stride.
  bool read_vertices_fast(const PlyElement& e, const std::vector<Role>& roles,
                          BinarySource& source) {
    const std::size_t stride = e.fixed_size();
    std::size_t offset[3] = {0, 0, 0};
    PlyScalar type = PlyScalar::u8;
    std::size_t at = 0;
    bool first = true;
    for (std::size_t k = 0; k < roles.size(); ++k) {
      const Role r = roles[k];
      if (r == Role::x || r == Role::y || r == Role::z) {
        if (!first && e.properties[k].type != type)
          return false;
        type = e.properties[k].type;
        first = false;
        offset[static_cast<int>(r) - static_cast<int>(Role::x)] = at;
      }
      at += ply_scalar_size(e.properties[k].type);
    }
    if (stride == 0 || (type != PlyScalar::f32 && type != PlyScalar::f64))
      return false;
    // read_elements checked that the whole element is in the file.
    read_ply_fixed_vertices(source.position(), stride, offset, type, source.swaps(),
                            soup_.positions, worker_threads());
    source.advance(stride * soup_.positions.size());
    return true;
  }

  //! Faces, triangle strips, edges and any other element.
  template <class Source>
  void read_records(const PlyElement& e, const std::vector<Role>& roles, Source& source) {
    const bool faces = e.name == "face", strips = e.name == "tristrips", edges = e.name == "edge";
    const bool colors = faces && wants_colors(roles);
    if (faces) {
      info_.declared_faces += static_cast<std::size_t>(e.count);
      reserve_huge(soup_.face_begin, soup_.face_begin.size() + e.count);
      reserve_huge(soup_.corner_vertices, soup_.corner_vertices.size() + 3 * e.count);
      if (colors) {
        attributes_->face_colors.reserve(e.count);
        attributes_->face_color_channels = ply_color_channels(roles);
      }
    }
    if constexpr (std::is_same_v<Source, BinarySource>) {
      if (faces && !colors && read_faces_fast(e, roles, source))
        return;
    }
    Rgba color;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      color = Rgba();
      bool clamped = false;
      for (std::size_t k = 0; k < roles.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        const Role r = roles[k];
        if (r == Role::indices) {
          read_list(e, i, p, source);
        } else if (r == Role::vertex1 || r == Role::vertex2) {
          std::int64_t v = 0;
          if (!source.integer(p.type, v))
            throw unreadable(e, i, p);
          if (v < 0 || static_cast<std::uint64_t>(v) >= vertices_) {
            throw ReadError(where() + item(e, i) + line_of(e.name, i) + ": property '" + p.name +
                            "' is vertex index " + std::to_string(v) + ", but the file has " +
                            counted(vertices_, "vertex") + " (indices count from 0)");
          }
        } else if (is_color(r) && colors) {
          double value = 0;
          if (!source.real(p.type, value))
            throw unreadable(e, i, p);
          set_color_channel(color, r, ply_channel(value, p.type));
          clamped = clamped || ply_channel_clamps(value, p.type);
        } else if (!skip_property(p, source)) {
          throw unreadable(e, i, p);
        }
      }
      colors_clamped_[1] += clamped;
      if (faces) {
        if (add_face(i) && colors) {
          push_color(attributes_->face_colors, attributes_->face_color_missing,
                     soup_.num_faces() - 1, &color);
        }
      } else if (strips) {
        add_strip(i);
      } else if (edges) {
        ++info_.dangling_edges;
      }
    }
  }

  //! Binary faces whose only property is `list uchar int|uint vertex_indices`.
  bool read_faces_fast(const PlyElement& e, const std::vector<Role>& roles, BinarySource& source) {
    if (roles.size() != 1 || e.properties[0].count_type != PlyScalar::u8 ||
        (e.properties[0].type != PlyScalar::i32 && e.properties[0].type != PlyScalar::u32)) {
      return false;
    }
    const bool swap = source.swaps();
    // All n-gons of one n with valid indices (almost every file): in blocks, in parts.
    if (const std::size_t bytes =
            read_ply_uniform_faces(source.position(), source.remaining(), e.count,
                                   e.properties[0].type, swap, soup_, worker_threads())) {
      source.advance(bytes);
      return true;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (source.remaining() < 1)
        throw unreadable(e, i, e.properties[0]);
      const unsigned n = *source.position();
      source.advance(1);
      if (source.remaining() / 4 < n) {
        throw ReadError(where() + item(e, i) + " claims " + std::to_string(n) +
                        " corners, more than the rest of the file holds");
      }
      const unsigned char* p = source.position();
      corners_.resize(n);
      for (unsigned c = 0; c < n; ++c) {
        // Each branch widened on its own: `?:` would convert a negative int32 to uint32.
        corners_[c] = e.properties[0].type == PlyScalar::i32
                          ? std::int64_t{load<std::int32_t>(p + 4 * c, swap)}
                          : std::int64_t{load<std::uint32_t>(p + 4 * c, swap)};
      }
      source.advance(4 * std::size_t(n));
      add_face(i);
    }
    return true;
  }

  template <class Source>
  void read_list(const PlyElement& e, std::uint64_t i, const PlyProperty& p, Source& source) {
    std::int64_t n = 0;
    if (!source.integer(p.count_type, n))
      throw unreadable(e, i, p);
    if (n < 0) {
      throw ReadError(where() + item(e, i) + " has a negative corner count (" + std::to_string(n) +
                      ")");
    }
    if (!source.can_hold(p.type, static_cast<std::uint64_t>(n))) {
      throw ReadError(where() + item(e, i) + " claims " + std::to_string(n) +
                      " corners, more than the rest of the file holds");
    }
    corners_.resize(static_cast<std::size_t>(n));
    for (std::int64_t& c : corners_) {
      if (!source.integer(p.type, c))
        throw unreadable(e, i, p);
    }
  }

  Index vertex_index(const char* what, std::uint64_t i, std::int64_t c) const {
    if (c < 0 || std::uint64_t(c) >= vertices_) {
      throw ReadError(where() + "PLY " + what + " " + std::to_string(i + 1) + line_of(what, i) +
                      " refers to vertex index " + std::to_string(c) + ", but the file has " +
                      counted(vertices_, "vertex") + " (indices count from 0)");
    }
    return static_cast<Index>(c);
  }

  //! " (line N)" for item i of element `name` in an ascii PLY file, else empty. Walks the body
  //! again: only for an error message.
  std::string line_of(std::string_view name, std::uint64_t i) const {
    if (header_.format != Format::ascii)
      return {};
    for (std::size_t k = 0; k < header_.elements.size(); ++k) {
      if (header_.elements[k].name == name) {
        const std::size_t line = ascii_ply_item_line(file_.view(), header_, k, i);
        return line == 0 ? std::string() : " (line " + std::to_string(line) + ")";
      }
    }
    return {};
  }

  //! Refuses a vertex with a coordinate that is nan or infinite, naming it as the file does.
  void check_finite() const {
    for (std::size_t v = 0; v < soup_.positions.size(); ++v) {
      const Point& p = soup_.positions[v];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        throw InvalidSoupError(where() + "PLY vertex " + std::to_string(v + 1) + " of " +
                               std::to_string(soup_.positions.size()) + " (index " +
                               std::to_string(v) + ")" + line_of("vertex", v) +
                               " has a non-finite coordinate (nan or inf)");
      }
    }
  }

  //! Appends face record i from corners_ (formats.h: 1 or 2 corners repeat the last one up to a
  //! triangle; none: counted, not appended). Returns whether a soup face was appended.
  bool add_face(std::uint64_t i) {
    if (corners_.empty()) {
      ++info_.faces_without_corners;
      return false;
    }
    for (std::int64_t c : corners_)
      soup_.corner_vertices.push_back(vertex_index("face", i, c));
    for (std::size_t k = corners_.size(); k < 3; ++k)
      soup_.corner_vertices.push_back(soup_.corner_vertices.back());
    soup_.face_begin.push_back(static_cast<Index>(soup_.corner_vertices.size()));
    return true;
  }

  //! Strip record i from corners_: -1 restarts; triangle k of a run is (a, b, c) for even k and
  //! (b, a, c) for odd k, so all share the strip's orientation (as MeshLab reads them).
  //! Triangles that repeat a vertex only link runs (a b c c d ...): counted as strip joins, not
  //! faces (MeshLab drops them too). A run of 1 or 2 vertices, or a strip with no vertex at all,
  //! makes no triangle: counted in `empty_records`.
  void add_strip(std::uint64_t i) {
    std::size_t run = 0;
    Index a = 0, b = 0;
    bool any_vertex = false;
    for (std::int64_t c : corners_) {
      if (c == -1) {
        if (run == 1 || run == 2)
          ++info_.empty_records;
        run = 0;
        continue;
      }
      any_vertex = true;
      const Index v = vertex_index("tristrips", i, c);
      if (run >= 2 && (a == b || b == v || a == v)) {
        ++info_.strip_joins;
      } else if (run >= 2) {
        ++info_.declared_faces;
        const bool even = run % 2 == 0;
        soup_.add_polygon({even ? a : b, even ? b : a, v});
      }
      a = b;
      b = v;
      ++run;
    }
    if (run == 1 || run == 2 || !any_vertex)  // a short last run, or a strip of restarts only
      ++info_.empty_records;
  }

  const MappedFile& file_;
  ReadInfo& info_;
  Soup& soup_;
  MeshAttributes* attributes_;
  PlyHeader header_;
  std::uint64_t vertices_ = 0;              //!< the vertex count the header declares
  std::size_t colors_clamped_[2] = {0, 0};  //!< vertices, faces with a channel ply_channel_clamps()
  std::vector<std::int64_t> corners_;
};

}  // namespace

void read_ply(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  PlyReader(file, soup, info, attributes).read();
}

}  // namespace meshbridge::detail
