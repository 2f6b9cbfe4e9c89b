// SPDX-License-Identifier: GPL-3.0-or-later
// Binary OFF: OpenMesh's layout (little-endian) or Geomview's (big-endian, a colour count after
// each face), whichever accounts for every byte of the file.

#include "io/huge_pages.h"
#include "io/read_off.h"
#include "meshbridge/counted.h"
#include "meshbridge/errors.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace meshbridge::detail {

namespace {

class OffBinaryReader {
 public:
  OffBinaryReader(const MappedFile& file, const char* body, Soup& soup, ReadInfo& info,
                  MeshAttributes* attributes)
      : file_(file), body_(body), soup_(soup), info_(info), attributes_(attributes) {}

  // Binary OFF comes in two layouts: OpenMesh's (little-endian, as x86 writes it, and nothing
  // after a face's indices) and Geomview's specification (big-endian 32-bit words, each face
  // followed by a colour count and that many floats). The layout that accounts for every byte of
  // the file is read; when none does, OpenMesh's is read and names what is wrong.
  struct BinaryLayout {
    bool big_endian = false;
    bool color_counts = false;
  };
  static std::uint32_t load(const char* p, bool big_endian) {
    std::uint32_t w = 0;
    std::memcpy(&w, p, 4);
    return big_endian ? __builtin_bswap32(w) : w;
  }
  static std::uint64_t vertex_floats(const OffHeader& h) {
    return 3 + (h.normals ? 3 : 0) + (h.colors ? 3 : 0) + (h.texcoords ? 2 : 0);
  }
  // True if the body from `p` is exactly the counts, vertices and faces of `layout`.
  bool fits(const OffHeader& h, const char* p, BinaryLayout layout) const {
    const char* end = file_.end();
    if (end - p < 12)
      return false;
    const std::uint64_t nv = load(p, layout.big_endian), nf = load(p + 4, layout.big_endian);
    p += 12;
    if (nv * vertex_floats(h) * 4 > std::uint64_t(end - p))
      return false;
    p += nv * vertex_floats(h) * 4;
    for (std::uint64_t f = 0; f < nf; ++f) {
      if (end - p < 4)
        return false;
      const std::uint64_t n = load(p, layout.big_endian);
      if (n == 0 || (n + 1) * 4 > std::uint64_t(end - p))
        return false;
      p += (n + 1) * 4;
      if (layout.color_counts) {
        if (end - p < 4)
          return false;
        const std::uint64_t colors = load(p, layout.big_endian);
        if (colors > 4 || (colors + 1) * 4 > std::uint64_t(end - p))
          return false;
        p += (colors + 1) * 4;
      }
    }
    return p == end || only_padding(p);
  }
  //! True if the bytes from `p` to the end are line ends, blanks or NULs (padding after the
  //! last face, such as a newline a program added).
  bool only_padding(const char* p) const {
    return std::all_of(p, file_.end(),
                       [](char c) { return c == '\n' || c == '\r' || c == ' ' || c == '\0'; });
  }
  //! True if the counts at `p` in `layout` leave room for the vertices and the faces (a face
  //! takes at least 8 bytes) in what follows: the layout to read when none fits exactly.
  bool plausible(const OffHeader& h, const char* p, BinaryLayout layout) const {
    const std::uint64_t left = static_cast<std::uint64_t>(file_.end() - p);
    if (left < 12)
      return false;
    const std::uint64_t nv = load(p, layout.big_endian), nf = load(p + 4, layout.big_endian);
    return nv * vertex_floats(h) * 4 + nf * 8 <= left - 12;
  }

  void read(const OffHeader& h) {
    const char* p = body_;
    BinaryLayout layout;  // OpenMesh's, unless only another one fits the file
    bool fitted = false;
    for (const BinaryLayout candidate : {BinaryLayout{false, false}, BinaryLayout{true, true},
                                         BinaryLayout{false, true}, BinaryLayout{true, false}}) {
      if (fits(h, p, candidate)) {
        layout = candidate;
        fitted = true;
        break;
      }
    }
    // None fits (a truncated or damaged file): the byte order whose counts the file can hold,
    // so that the error names the file's own counts.
    if (!fitted && !plausible(h, p, layout) && plausible(h, p, BinaryLayout{true, true}))
      layout = BinaryLayout{true, true};
    const char* end = file_.end();
    const auto left = [&] { return static_cast<std::uint64_t>(end - p); };
    const auto word = [&] {
      const std::uint32_t w = load(p, layout.big_endian);
      p += 4;
      return w;
    };
    const auto real = [&] {
      const std::uint32_t w = word();
      float x = 0;
      std::memcpy(&x, &w, 4);
      return x;
    };
    if (left() < 12)
      fail("binary OFF ends before its vertex, face and edge counts");
    const std::uint32_t nv = word(), nf = word();
    word();
    const std::uint64_t floats = vertex_floats(h);
    if (std::uint64_t(nv) * floats * 4 > left()) {
      fail("binary OFF declares " + std::to_string(nv) + " vertices (" +
           std::to_string(std::uint64_t(nv) * floats * 4) + " bytes) but only " +
           std::to_string(left()) + " bytes follow its header (a truncated file or a false count)");
    }
    if (std::uint64_t(nf) * 4 > left() - std::uint64_t(nv) * floats * 4) {
      fail("binary OFF declares " + std::to_string(nf) + " faces but only " +
           std::to_string(left() - std::uint64_t(nv) * floats * 4) + " bytes follow its vertices");
    }
    info_.declared_vertices = nv;
    info_.declared_faces = nf;
    reserve_huge(soup_, nv, nf, 3 * std::size_t(nf));
    const bool colors = attributes_ != nullptr && h.colors;
    if (colors)
      attributes_->vertex_color_channels = kRgbChannels;  // 3 floats
    for (std::uint32_t v = 0; v < nv; ++v) {
      float values[11];
      for (std::uint64_t i = 0; i < floats; ++i)
        values[i] = real();
      soup_.positions.push_back(Point(values[0], values[1], values[2]));
      if (colors) {
        const float* c = values + 3 + (h.normals ? 3 : 0);
        notes_.vertex_colors_clamped += off_color_clamped(c[0], true) ||
                                        off_color_clamped(c[1], true) ||
                                        off_color_clamped(c[2], true);
        attributes_->vertex_colors.push_back(Rgba{off_color_byte(c[0], true),
                                                  off_color_byte(c[1], true),
                                                  off_color_byte(c[2], true), 255});
      }
    }
    std::vector<Index> corners;
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (left() < 4) {
        fail("binary OFF ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
      }
      const std::uint32_t n = word();
      if (std::uint64_t(n) * 4 > left()) {
        fail("binary OFF face " + std::to_string(f + 1) + " claims " + std::to_string(n) +
             " corners, more than the rest of the file holds");
      }
      corners.clear();
      for (std::uint32_t c = 0; c < n; ++c) {
        const std::int32_t index = static_cast<std::int32_t>(word());
        if (index < 0 || std::uint32_t(index) >= nv) {
          fail("binary OFF face " + std::to_string(f + 1) + " refers to vertex index " +
               std::to_string(index) + ", but the file has " + counted(nv, "vertex") +
               " (OFF counts from 0)");
        }
        corners.push_back(static_cast<Index>(index));
      }
      add_off_face(corners, soup_, info_);
      if (layout.color_counts) {  // a count, then that many floats (checked: the layout may
                                  // be read without fitting, see plausible())
        if (left() < 4)
          fail("binary OFF ends in face " + std::to_string(f + 1) + ", before its colour count");
        const std::uint32_t color_values = word();
        if (4 * std::uint64_t(color_values) > left()) {
          fail("binary OFF face " + std::to_string(f + 1) + " claims " +
               std::to_string(color_values) + " colour values, more than the rest of the file " +
               "holds");
        }
        notes_.face_colors += color_values > 0 ? 1 : 0;
        p += 4 * std::uint64_t(color_values);
      }
    }
    if (p != end && !only_padding(p)) {
      fail("binary OFF: " + std::to_string(left()) +
           " bytes follow its last face (neither OpenMesh's layout nor Geomview's fits the file)");
    }
    info_.trailing_bytes = left();  // padding: counted, as after a binary PLY
  }

  const OffBinaryNotes& notes() const { return notes_; }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ReadError(file_.path() + ": " + what);
  }

  const MappedFile& file_;
  const char* body_;
  Soup& soup_;
  ReadInfo& info_;
  MeshAttributes* attributes_;
  OffBinaryNotes notes_;
};

}  // namespace

OffBinaryNotes read_off_binary(const MappedFile& file, const char* body, const OffHeader& h,
                               Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  OffBinaryReader reader(file, body, soup, info, attributes);
  reader.read(h);
  return reader.notes();
}

}  // namespace meshbridge::detail
