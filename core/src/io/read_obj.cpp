// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ reader: v (x y z [w] [r g b [a]]), vt, vn, f/l/p with every index form (v, v/vt, v//vn,
// v/vt/vn, negative = relative), backslash line continuations, o/g/usemtl as face groups.
// mtllib and every other record are skipped (never opened).

#include "io/formats.h"
#include "io/text_scanner.h"
#include "meshbridge/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace meshbridge::detail {

namespace {

class ObjReader {
 public:
  ObjReader(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes)
      : file_(file),
        soup_(soup),
        info_(info),
        attributes_(attributes),
        in_(file.data(), file.end(), true, true) {}

  void read() {
    while (!in_.at_end()) {
      if (in_.position() - released_ > kReleaseEvery) {
        released_ = in_.position();
        file_.release_before(released_);
      }
      const std::string_view keyword = in_.word();
      if (keyword == "v")
        vertex();
      else if (keyword == "vt" || keyword == "vn")
        ++texcoords_or_normals_;
      else if (keyword == "f" || keyword == "fo")
        face();
      else if (keyword == "l")
        line_record();
      else if (keyword == "p")
        point_record();
      else if (attributes_ != nullptr && (keyword == "o" || keyword == "g" || keyword == "usemtl"))
        group(keyword);
      in_.next_line();  // anything else (comments, mtllib, s, curves): skipped
    }
    info_.declared_vertices = soup_.num_vertices();
    if (attributes_ != nullptr && !attributes_->vertex_colors.empty())
      attributes_->vertex_colors.resize(soup_.num_vertices(), Rgba{255, 255, 255, 255});
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_.path() + ": line " + std::to_string(in_.line()) + ": " + what);
  }

  void vertex() {
    double values[7];
    int n = 0;
    while (n < 7 && !in_.at_line_end()) {
      if (!in_.number(values[n])) {
        const std::string_view bad = in_.word();
        fail("vertex " + std::to_string(soup_.num_vertices() + 1) + ": '" + clip(bad) +
             "' is not a number a double can hold (expected 'v x y z')");
      }
      ++n;
    }
    if (n < 3) {
      fail("vertex " + std::to_string(soup_.num_vertices() + 1) + " has " + std::to_string(n) +
           " coordinate(s), expected 3");
    }
    soup_.positions.push_back(Point(values[0], values[1], values[2]));
    if (attributes_ != nullptr && n >= 6) {
      // x y z r g b [a]: colours as floats in [0, 1].
      auto& colors = attributes_->vertex_colors;
      colors.resize(soup_.num_vertices() - 1, Rgba{255, 255, 255, 255});
      colors.push_back(Rgba{to_byte(values[3]), to_byte(values[4]), to_byte(values[5]),
                            n == 7 ? to_byte(values[6]) : std::uint8_t(255)});
    } else if (attributes_ != nullptr && !attributes_->vertex_colors.empty()) {
      attributes_->vertex_colors.push_back(Rgba{255, 255, 255, 255});
    }
  }

  static std::uint8_t to_byte(double unit) {
    const double clamped = std::isfinite(unit) ? std::clamp(unit, 0.0, 1.0) : 0.0;
    return static_cast<std::uint8_t>(std::lround(clamped * 255.0));
  }

  static std::string clip(std::string_view text) {
    std::string out(text.substr(0, 40));
    for (char& c : out) {
      if (static_cast<unsigned char>(c) < 32)
        c = '?';
    }
    return out;
  }

  // One corner "v", "v/vt", "v//vn" or "v/vt/vn": the vertex index, 0-based (kNoIndex if a
  // relative index points before the first vertex; validate_soup names out-of-range ones).
  Index corner(const char* what) {
    const std::string_view text = in_.word();
    const char* first = text.data();
    const char* last = first + text.size();
    std::int64_t index = 0;
    const char* end = parse_integer(first, last, index);
    if (end == nullptr) {
      const bool digits = first != last && (std::isdigit(static_cast<unsigned char>(*first)) ||
                                            *first == '-' || *first == '+');
      fail(std::string(what) + " corner '" + clip(text) + "' " +
           (digits ? std::string("is not an index MeshBridge can hold (beyond 64 bits)")
                   : std::string("has no vertex index") +
                         (first != last && *first == '/'
                              ? " before its texture coordinate or normal"
                              : " (expected 'v', 'v/vt', 'v//vn' or 'v/vt/vn')")));
    }
    // The texture coordinate and normal indices are checked for form only.
    for (int part = 0; end != last && part < 2; ++part) {
      if (*end != '/')
        break;
      ++end;
      std::int64_t ignored = 0;
      if (end != last && *end != '/') {
        end = parse_integer(end, last, ignored);
        if (end == nullptr)
          break;
      }
    }
    if (end != last)
      fail(std::string(what) + " corner '" + clip(text) +
           "' is not 'v', 'v/vt', 'v//vn' or 'v/vt/vn'");
    const std::int64_t count = static_cast<std::int64_t>(soup_.num_vertices());
    if (index == 0)
      fail(std::string(what) + " corner '" + clip(text) + "': OBJ indices start at 1 (or -1)");
    if (index > 0) {
      if (index > std::int64_t(kNoIndex))
        fail(std::string(what) + " corner '" + clip(text) + "': index beyond 32 bits");
      return static_cast<Index>(index - 1);
    }
    if (-index > count) {
      fail(std::string(what) + " corner '" + clip(text) + "' refers to vertex " +
           std::to_string(count + index + 1) + ", before the first vertex (" +
           std::to_string(count) + " so far)");
    }
    return static_cast<Index>(count + index);
  }

  void read_corners(const char* what) {
    corners_.clear();
    while (!in_.at_line_end())
      corners_.push_back(corner(what));
  }

  void face() {
    read_corners("face");
    ++info_.declared_faces;
    if (corners_.empty()) {
      ++info_.faces_without_corners;
      return;
    }
    while (corners_.size() < 3)
      corners_.push_back(corners_.back());
    soup_.add_polygon(corners_);
  }

  void line_record() {
    read_corners("line");
    if (corners_.size() >= 2)
      info_.dangling_edges += corners_.size() - 1;
    else
      info_.lone_points += corners_.size();
  }

  void point_record() {
    read_corners("point");
    info_.lone_points += corners_.size();
  }

  void group(std::string_view keyword) {
    in_.skip_blanks();
    const char* start = in_.position();
    in_.word();
    while (!in_.at_line_end())
      in_.word();
    std::string name(keyword);
    name += ' ';
    name.append(start, static_cast<std::size_t>(in_.position() - start));
    while (!name.empty() && TextScanner::is_blank_or_newline(name.back()))
      name.pop_back();
    attributes_->face_groups.push_back(FaceGroup{name, static_cast<Index>(soup_.num_faces())});
  }

  const MappedFile& file_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  TextScanner in_;
  std::vector<Index> corners_;
  std::size_t texcoords_or_normals_ = 0;
  static constexpr std::ptrdiff_t kReleaseEvery = 8 << 20;  // bytes of the map kept behind
  const char* released_ = file_.data();
};

// Counts 'v' and 'f' records (and the blanks of the 'f' lines, a bound on their corners) with
// memchr, so the soup is allocated once: a few percent of the parse instead of reallocations.
void reserve_for(const MappedFile& file, Soup& soup) {
  std::size_t vertices = 0, faces = 0, corners = 0;
  const char* p = file.data();
  const char* end = file.end();
  while (p < end) {
    const char* line_end = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (line_end == nullptr)
      line_end = end;
    if (line_end - p >= 2 && (p[1] == ' ' || p[1] == '\t')) {
      if (p[0] == 'v') {
        ++vertices;
      } else if (p[0] == 'f') {
        ++faces;
        corners += static_cast<std::size_t>(std::count(p + 1, line_end, ' '));
      }
    }
    if (line_end == end)
      break;
    p = line_end + 1;
  }
  soup.reserve(vertices, faces, corners);
}

}  // namespace

void read_obj(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  reserve_for(file, soup);
  file.release_before(file.end());  // the counting pass touched every page
  ObjReader(file, soup, info, attributes).read();
}

}  // namespace meshbridge::detail
