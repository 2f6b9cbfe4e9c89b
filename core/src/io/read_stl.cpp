// SPDX-License-Identifier: GPL-3.0-or-later
// The STL reader: binary (decided by size: 84 + 50 n bytes, whatever the header says) and ascii,
// corners welded by exact position into shared vertices in order of first appearance.
#include "io/formats.h"
#include "io/position_weld.h"
#include "io/stl_facets.h"
#include "io/text_scanner.h"
#include "parallel_parts.h"

#include "meshbridge/errors.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace meshbridge::detail {

namespace {

bool equals_ignoring_case(std::string_view word, std::string_view lower) {
  if (word.size() != lower.size())
    return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char c = word[i] >= 'A' && word[i] <= 'Z' ? char(word[i] - 'A' + 'a') : word[i];
    if (c != lower[i])
      return false;
  }
  return true;
}

//! The stretch of the file a binary STL reader keeps mapped behind and ahead of it.
constexpr std::size_t kWindow = std::size_t(8) << 20;

//! Returns how many triangles have a non-zero attribute word (the 16 bits after each triangle:
//! 0 by the format, a colour in some programs) and a normal against their winding (not kept:
//! every writer recomputes normals from the corners).
FacetNotes read_binary(const MappedFile& file, std::uint32_t triangles, Soup& soup,
                       ReadInfo& info) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(file.data()) + 84;
  info.declared_faces = triangles;
  info.declared_vertices = 3 * std::size_t(triangles);
  std::atomic<std::size_t> attribute_words{0}, normals_reversed{0};
  std::atomic<bool> negative_zero{false};
  const auto keys = [&file, bytes, &attribute_words, &normals_reversed, &negative_zero](
                        std::size_t first, std::size_t count, FloatKey* out) {
    const unsigned char* facets = bytes + 50 * (first / 3);  // whole facets (CornerKeys)
    const CornerBits bits = facet_corner_keys(facets, count / 3, out);
    if (bits.non_finite) {  // the first such corner, for the message
      for (std::size_t c = first;; ++c) {
        const unsigned char* p = bytes + 50 * (c / 3) + 12 + 12 * (c % 3);
        for (int k = 0; k < 3; ++k) {
          if (!std::isfinite(little_endian_float(p + 4 * k))) {
            throw InvalidSoupError(file.path() + ": binary STL facet " + std::to_string(c / 3 + 1) +
                                   ", corner " + std::to_string(c % 3 + 1) +
                                   " has a non-finite coordinate");
          }
        }
      }
    }
    if (bits.negative_zero)
      negative_zero.store(true, std::memory_order_relaxed);
    const FacetNotes notes = facet_notes(facets, count / 3);
    if (notes.attribute_words > 0)
      attribute_words += notes.attribute_words;
    if (notes.normals_reversed > 0)
      normals_reversed += notes.normals_reversed;
    // Every 8 MiB of the file, the 8 MiB read before go back to the kernel (see
    // MappedFile::release_before), so the map adds a window to the peak memory, not the whole file,
    // and the 8 MiB after the next are mapped in one call. (At the start of a part that window may
    // end another part; a page it still reads is read back from the cache.)
    const std::size_t from = 84 + 50 * (first / 3), to = 84 + 50 * ((first + count + 2) / 3);
    if (from / kWindow != to / kWindow) {
      const char* border = file.data() + to / kWindow * kWindow;
      file.release_between(border - kWindow, border);
      if (static_cast<std::size_t>(file.end() - border) > kWindow)  // (no pointer past the map)
        file.prefault_between(border + kWindow,
                              border + std::min<std::size_t>(2 * kWindow, file.end() - border));
    }
  };
  file.prefault_between(file.data(), file.data() + std::min(file.size(), 2 * kWindow));
  weld_triangle_corners(3 * std::size_t(triangles), keys, soup, worker_threads());
  if (negative_zero.load()) {
    restore_negative_zeros(soup, [bytes](std::size_t c, float* xyz) {
      for (int k = 0; k < 3; ++k)
        xyz[k] = little_endian_float(bytes + 50 * (c / 3) + 12 + 12 * (c % 3) + 4 * k);
    });
  }
  return {attribute_words.load(), normals_reversed.load()};
}

// ASCII STL, read as the grammar it is: `solid NAME`, then facets (`facet normal x y z`,
// `outer loop`, three `vertex x y z`, `endloop`, `endfacet`), then `endsolid NAME`; several
// solids may follow each other. Keywords in any case; `outerloop` is taken for `outer loop`.
// Anything else is an error naming its line, so that no facet is dropped or cut to a triangle
// without a word; a missing `endloop`, `endfacet` or `endsolid` too, since a file cut short (a
// copy that stopped) would otherwise read as a whole one.
//! What an ASCII STL reader reads past: solid names, facet normals against the winding.
struct AsciiNotes {
  std::size_t named_solids = 0;
  std::size_t normals_reversed = 0;
};

AsciiNotes read_ascii(const MappedFile& file, const char* end, Soup& soup, ReadInfo& info) {
  std::size_t named_solids = 0, normals_reversed = 0;
  TextScanner in(after_byte_order_mark(file.data(), end), end);
  std::vector<float> corners;
  std::size_t triangles = 0;
  const auto next_word = [&] {
    while (!in.at_end() && in.at_line_end())
      in.next_line();
    return in.word();
  };
  // True if nothing but blank lines follows the cursor: a file cut off there.
  const auto ends_here = [&in] {
    TextScanner rest = in;
    while (!rest.at_end() && rest.at_line_end())
      rest.next_line();
    return rest.at_end();
  };
  // Every error names its line; one where the file ends says it may be cut short.
  const auto fail = [&](std::size_t line, const std::string& what) {
    const bool cut = ends_here() && what.find("truncated") == std::string::npos;
    throw ReadError(file.path() + ": ASCII STL line " + std::to_string(line) + ": " + what +
                    (cut ? "; the file ends there (truncated?)" : ""));
  };
  const auto quoted = [](std::string_view word) {
    return word.empty() ? std::string("the end of the file")
                        : "'" + std::string(word.substr(0, 40)) + "'";
  };
  std::string_view word = next_word();
  std::size_t open_solid = 0;  // the line of the `solid` not yet ended, or 0
  while (!word.empty()) {
    if (equals_ignoring_case(word, "solid")) {
      if (open_solid != 0) {
        fail(in.line(), "'solid' inside the solid of line " + std::to_string(open_solid) +
                            " (its 'endsolid' is missing)");
      }
      open_solid = in.line();
      named_solids += !in.at_line_end();
      in.next_line();  // the solid's name may be any words, "outer" included
      word = next_word();
      continue;
    }
    if (equals_ignoring_case(word, "endsolid")) {
      if (open_solid == 0)
        fail(in.line(), "'endsolid' without a 'solid' before it");
      open_solid = 0;
      in.next_line();
      word = next_word();
      continue;
    }
    if (open_solid == 0)
      fail(in.line(), quoted(word) + " where 'solid' or the end of the file was expected");
    if (!equals_ignoring_case(word, "facet"))
      fail(in.line(), quoted(word) + " where a facet, 'solid' or 'endsolid' was expected");
    const std::size_t facet_line = in.line();
    word = next_word();
    float normal[3] = {0, 0, 0};  // recomputed from the corners: not kept
    if (equals_ignoring_case(word, "normal")) {
      for (int i = 0; i < 3 && !in.at_line_end(); ++i) {
        const std::string_view value = in.word();
        double x = 0;
        if (parse_double(value.data(), value.data() + value.size(), x) ==
            value.data() + value.size())
          normal[i] = static_cast<float>(x);
      }
      word = next_word();
    }
    if (equals_ignoring_case(word, "outer")) {
      word = next_word();
      if (!equals_ignoring_case(word, "loop"))
        fail(in.line(), quoted(word) + " after 'outer' (expected 'outer loop')");
    } else if (!equals_ignoring_case(word, "outerloop")) {
      fail(in.line(), quoted(word) + " in facet " + std::to_string(triangles + 1) +
                          " (expected 'outer loop')");
    }
    int n = 0;
    for (word = next_word(); equals_ignoring_case(word, "vertex"); word = next_word(), ++n) {
      const std::size_t line = in.line();
      double x = 0, y = 0, z = 0;
      const bool ok = in.number(x) && in.number(y) && in.number(z) && std::isfinite(float(x)) &&
                      std::isfinite(float(y)) && std::isfinite(float(z));
      TextScanner after = in;  // a fourth number is no coordinate MeshBridge could keep
      double w = 0;
      if (ok && after.number(w)) {
        fail(line, "facet " + std::to_string(triangles + 1) + ", corner " + std::to_string(n + 1) +
                       ": more than 3 numbers after 'vertex'");
      }
      if (!ok) {
        fail(line, "facet " + std::to_string(triangles + 1) + ", corner " + std::to_string(n + 1) +
                       " is not 'vertex x y z' with three finite numbers (32-bit floats)");
      }
      if (n < 3)  // STL coordinates are 32-bit floats (binary STL stores nothing else)
        corners.insert(corners.end(), {float(x), float(y), float(z)});
    }
    if (n < 3 && (word.empty() || ends_here())) {
      fail(in.line(), "the file ends inside facet " + std::to_string(triangles + 1) + " after " +
                          std::to_string(n) + " of its 3 vertices" +
                          (word.empty() ? "" : ", at " + quoted(word)) + " (truncated)");
    }
    if (n != 3) {
      fail(facet_line, "facet " + std::to_string(triangles + 1) + " has " + std::to_string(n) +
                           " vertices; an STL facet is a triangle (3)");
    }
    for (const char* end : {"endloop", "endfacet"}) {
      if (!equals_ignoring_case(word, end)) {
        fail(in.line(), quoted(word) + " where facet " + std::to_string(triangles + 1) + " (line " +
                            std::to_string(facet_line) + ") needs '" + end + "'" +
                            (word.empty() || ends_here() ? " (a truncated file?)" : ""));
      }
      word = next_word();
    }
    const float* a = corners.data() + corners.size() - 9;
    normals_reversed += normal_against_winding(normal, a, a + 3, a + 6);
    ++triangles;
  }
  if (open_solid != 0) {
    fail(in.line(), "the file ends inside the solid of line " + std::to_string(open_solid) +
                        ", without 'endsolid' (a truncated file?)");
  }
  info.declared_faces = triangles;
  info.declared_vertices = 3 * triangles;
  const auto keys = [&corners](std::size_t first, std::size_t count, FloatKey* out) {
    for (std::size_t c = first; c < first + count; ++c)
      out[c - first] = float_key(corners[3 * c], corners[3 * c + 1], corners[3 * c + 2]);
  };
  weld_triangle_corners(3 * triangles, keys, soup, worker_threads());
  if (std::any_of(corners.begin(), corners.end(),
                  [](float x) { return x == 0 && std::signbit(x); })) {
    restore_negative_zeros(soup, [&corners](std::size_t c, float* xyz) {
      std::copy_n(corners.data() + 3 * c, 3, xyz);
    });
  }
  return {named_solids, normals_reversed};
}

//! The NotKept entry of facet normals against the winding.
NotKept reversed_normals(std::size_t facets) {
  return {
      "STL facet normals against the winding of their corners (written ones follow the "
      "winding)",
      facets, "facet", true};
}

//! Reads `facets` binary facets and names what they carry that is read past.
void read_binary_facets(const MappedFile& file, std::uint32_t facets, Soup& soup, ReadInfo& info,
                        MeshAttributes* attributes) {
  const FacetNotes notes = read_binary(file, facets, soup, info);
  if (attributes == nullptr)
    return;
  if (notes.attribute_words > 0) {
    attributes->not_kept.push_back({"binary STL facet attribute words (colours in some programs)",
                                    notes.attribute_words, "facet"});
  }
  if (notes.normals_reversed > 0)
    attributes->not_kept.push_back(reversed_normals(notes.normals_reversed));
  // Materialise's and VisCAM's whole-object colour in the 80-byte header.
  if (std::memcmp(file.data(), "COLOR=", 6) == 0 || std::memcmp(file.data(), "MATERIAL=", 9) == 0)
    attributes->not_kept.push_back({"binary STL header colour (COLOR=/MATERIAL=)", 1, "file"});
}

}  // namespace

void read_stl(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes* attributes) {
  const auto* head = reinterpret_cast<const unsigned char*>(file.data());
  const std::size_t size = file.size();
  const std::uint32_t triangles = size >= 84 ? little_endian_u32(head + 80) : 0;
  if (size >= 84 && 84 + 50 * std::uint64_t(triangles) == size) {
    read_binary_facets(file, triangles, soup, info, attributes);
    return;
  }
  // NUL bytes or a DOS end-of-file mark (^Z) after an ASCII STL: padding some programs write.
  const char* text_end = file.end();
  while (text_end != file.data() && (text_end[-1] == '\0' || text_end[-1] == '\x1a'))
    --text_end;
  TextScanner probe(after_byte_order_mark(file.data(), text_end), text_end);
  probe.skip_space_and_comments();
  // Binary data has NUL bytes (in its triangle count or coordinates) where ASCII STL has none: a
  // binary STL whose header begins with "solid" but whose size is wrong is named as binary.
  const std::size_t text_size = static_cast<std::size_t>(text_end - file.data());
  const bool has_nul =
      std::memchr(file.data(), '\0', std::min<std::size_t>(text_size, 4096)) != nullptr;
  const bool solid = equals_ignoring_case(probe.word(), "solid");
  // A header count other than the whole facets after it (0: written by a program that streams
  // its facets and cannot go back to count them): the facets the file holds are read, as
  // admesh and slicers read them, and the count is named.
  if (size > 84 && (size - 84) % 50 == 0 && (size - 84) / 50 <= 0xffffffffu &&
      (has_nul || !solid)) {
    const auto facets = static_cast<std::uint32_t>((size - 84) / 50);
    read_binary_facets(file, facets, soup, info, attributes);
    if (attributes != nullptr) {
      attributes->not_kept.push_back(
          {"binary STL header that counts " + std::to_string(triangles) + " triangles" +
               (triangles == 0 ? std::string(" (a streaming writer's)") : std::string()) +
               " before " + std::to_string(facets) + " whole facets, all read",
           1, "file", true});
    }
    return;
  }
  if (has_nul || !solid) {
    const std::uint64_t whole = size >= 84 ? (size - 84) / 50 : 0;
    const bool cut = size >= 84 && size < 84 + 50 * std::uint64_t(triangles);
    throw ReadError(
        file.path() +
        (solid ? ": binary data after a header that begins with 'solid', but not a "
                 "whole binary STL: a binary STL "
               : ": neither ASCII STL (no 'solid') nor binary STL: a binary STL ") +
        (size >= 84 ? "whose header counts " + std::to_string(triangles) + " triangles has " +
                          std::to_string(84 + 50 * std::uint64_t(triangles)) + " bytes"
                    : std::string("has at least 84 bytes")) +
        ", this file has " + std::to_string(size) +
        (cut ? " (" + std::to_string(whole) + " whole facets: a truncated file?)" : std::string()) +
        other_format_hint(file.view(), Format::stl));
  }
  const AsciiNotes notes = read_ascii(file, text_end, soup, info);
  info.trailing_bytes = static_cast<std::size_t>(file.end() - text_end);
  if (attributes != nullptr && notes.named_solids > 0)
    attributes->not_kept.push_back({"ASCII STL solid names", notes.named_solids, "solid"});
  if (attributes != nullptr && notes.normals_reversed > 0)
    attributes->not_kept.push_back(reversed_normals(notes.normals_reversed));
}

}  // namespace meshbridge::detail
