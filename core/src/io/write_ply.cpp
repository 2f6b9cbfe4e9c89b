// SPDX-License-Identifier: GPL-3.0-or-later
// The PLY writer: binary little endian (default) or ascii; positions as float, or as double when
// asked, when the input had doubles, or when some coordinate is not exactly a float (so writing
// never rounds a position); per-vertex and per-face colours where the attributes have them.
#include "io/formats.h"
#include "io/text_output.h"

#include "meshbridge/errors.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

namespace {

//! True if every coordinate reads back unchanged as a 32-bit float.
bool positions_are_floats(const Soup& soup) {
  for (const Point& p : soup.positions) {
    for (int i = 0; i < 3; ++i) {
      if (static_cast<double>(static_cast<float>(p[i])) != p[i])
        return false;
    }
  }
  return true;
}

bool is_little_endian_machine() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

//! Little-endian bytes into 1 MiB blocks handed to `out`.
class BinaryOutput {
 public:
  explicit BinaryOutput(AtomicOutput& out) : out_(out), buffer_(kBlock) {}
  //! Appends `value` in the machine's byte order: little endian on every target MeshBridge
  //! builds for (checked in write_ply).
  template <class T>
  void put(T value) {
    if (used_ + sizeof(T) > kBlock)
      flush();
    std::memcpy(buffer_.data() + used_, &value, sizeof(T));
    used_ += sizeof(T);
  }
  void flush() {
    out_.write(buffer_.data(), used_);
    used_ = 0;
  }

 private:
  static constexpr std::size_t kBlock = 1 << 20;
  AtomicOutput& out_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
};

//! The channels to write: those the input had, or all four if it named none.
std::uint8_t nonzero_channels(std::uint8_t channels) {
  return (channels & kRgbaChannels) != 0 ? channels & kRgbaChannels : kRgbaChannels;
}

//! "property uchar red" ... for each channel of `channels`, in PLY's usual order.
std::string channel_properties(std::uint8_t channels) {
  std::string header;
  for (const auto& [bit, name] :
       {std::pair{kRedChannel, "red"}, std::pair{kGreenChannel, "green"},
        std::pair{kBlueChannel, "blue"}, std::pair{kAlphaChannel, "alpha"}}) {
    if ((channels & bit) != 0)
      header += std::string("property uchar ") + name + "\n";
  }
  return header;
}

void put_channels(BinaryOutput& bytes, const Rgba& c, std::uint8_t channels) {
  const std::uint8_t values[4] = {c.r, c.g, c.b, c.a};
  for (int i = 0; i < 4; ++i) {
    if ((channels & (1 << i)) != 0)
      bytes.put<std::uint8_t>(values[i]);
  }
}

void put_channels(TextOutput& text, const Rgba& c, std::uint8_t channels) {
  const std::uint8_t values[4] = {c.r, c.g, c.b, c.a};
  for (int i = 0; i < 4; ++i) {
    if ((channels & (1 << i)) != 0)
      text.ch(' ').number(unsigned(values[i]));
  }
}

}  // namespace

void write_ply(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions& options) {
  static_assert(sizeof(float) == 4 && sizeof(double) == 8, "PLY float and double");
  if (options.binary && !is_little_endian_machine())
    throw WriteError(out.target() + ": binary PLY is written on little-endian machines only");
  const Soup& soup = mesh.soup;
  const bool doubles = options.double_precision ||
                       (attributes != nullptr && attributes->double_precision) ||
                       !positions_are_floats(soup);
  const bool vertex_colors = attributes != nullptr && !attributes->vertex_colors.empty();
  const bool face_colors = attributes != nullptr && !attributes->face_colors.empty();
  const std::uint8_t vertex_channels =
      vertex_colors ? nonzero_channels(attributes->vertex_color_channels) : 0;
  const std::uint8_t face_channels =
      face_colors ? nonzero_channels(attributes->face_color_channels) : 0;
  std::size_t max_arity = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    max_arity = std::max(max_arity, soup.arity(f));
  const bool short_count = max_arity <= 255;
  if (soup.num_vertices() > 0x7FFFFFFFu)
    throw WriteError(out.target() + ": more than 2^31 - 1 vertices do not fit a PLY int index");

  std::string header = "ply\nformat ";
  header += options.binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
  header += "comment written by MeshBridge\n";
  header += "element vertex " + std::to_string(soup.num_vertices()) + "\n";
  for (const char* axis : {"x", "y", "z"})
    header += std::string("property ") + (doubles ? "double " : "float ") + axis + "\n";
  if (vertex_colors)
    header += channel_properties(vertex_channels);
  header += "element face " + std::to_string(soup.num_faces()) + "\n";
  header += short_count ? "property list uchar int vertex_indices\n"
                        : "property list int int vertex_indices\n";
  if (face_colors)
    header += channel_properties(face_channels);
  header += "end_header\n";
  out.write(header);

  const auto vertex_color = [&](std::size_t v) {
    return color_of(attributes->vertex_colors, input_vertex(mesh, v));
  };
  const auto face_color = [&](std::size_t f) {
    return color_of(attributes->face_colors, input_face(mesh, f));
  };

  if (options.binary) {
    BinaryOutput bytes(out);
    for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
      const Point& p = soup.positions[v];
      for (int i = 0; i < 3; ++i) {
        if (doubles)
          bytes.put<double>(p[i]);
        else
          bytes.put<float>(static_cast<float>(p[i]));
      }
      if (vertex_colors) {
        put_channels(bytes, vertex_color(v), vertex_channels);
      }
    }
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const PolygonView polygon = soup.polygon(f);
      if (short_count)
        bytes.put<std::uint8_t>(static_cast<std::uint8_t>(polygon.size()));
      else
        bytes.put<std::int32_t>(static_cast<std::int32_t>(polygon.size()));
      for (Index v : polygon)
        bytes.put<std::int32_t>(static_cast<std::int32_t>(v));
      if (face_colors) {
        put_channels(bytes, face_color(f), face_channels);
      }
    }
    bytes.flush();
    return;
  }
  TextOutput text(out);
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v];
    for (int i = 0; i < 3; ++i) {
      if (i > 0)
        text.ch(' ');
      if (doubles) {
        text.number(p[i]);  // the shortest text that reads back to the same double
      } else {
        char digits[32];  // the shortest text that reads back to the same float
        const auto end = std::to_chars(digits, digits + sizeof digits, static_cast<float>(p[i]));
        text.text(std::string_view(digits, static_cast<std::size_t>(end.ptr - digits)));
      }
    }
    if (vertex_colors) {
      put_channels(text, vertex_color(v), vertex_channels);
    }
    text.ch('\n');
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    text.number(unsigned(polygon.size()));
    for (Index v : polygon)
      text.ch(' ').number(unsigned(v));
    if (face_colors) {
      put_channels(text, face_color(f), face_channels);
    }
    text.ch('\n');
  }
  text.flush();
}

}  // namespace meshbridge::detail
