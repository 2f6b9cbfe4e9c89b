// SPDX-License-Identifier: GPL-3.0-or-later
// Counts the red, green and violet pixels of a screenshot (binary PPM, P6, maxval 255), for the
// real-GUI tests: defect tubes are pure red / pure green, lit by MeshLab's lights, so a pixel
// counts as red when R >= 120 and G, B <= 60 (green likewise). Self-intersecting faces are violet
// (140, 0, 255), lit (about (158, 0, 255) facing the light): B >= 100, G <= 50, R between 0.3
// and 0.8 of B and at least G + 40 (magenta pinch markers have R = B; MeshLab's blue background
// has R = G, and passes the rest where it is (50, 50, 100)). MeshLab's pink selection overlay, its
// trackball lines and anti-aliased grey edges do not count.
// For the real-file tests (gui_realworld.sh) it also counts: selection pixels, MeshLab's pink
// overlay on the selected faces (the faces at the defects, which Detect selects): R >= G + 30, G
// and B within 12 of each other, G > 60 (the dark rim of a red tube is not pink); MeshLab's
// background, a blue gradient with R = G (within 2) and B >= 1.7 R, near black (every channel <= 8)
// at the top, (113, 113, 226) at the bottom; grey pixels, the shaded model (channels within 12 of
// each other, the brightest >= 40); and model pixels, all that is not background (grey surface,
// defect colours, selection, the trackball's thin lines).
//
// Usage: meshbridge_count_pixels IMAGE.ppm [X Y W H]    (the rectangle defaults to the image)
// Prints: width=, height=, pixels= (in the rectangle), red=, green=, violet=, selection=,
// background=, grey=, model=.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

long parse(const std::string& s, const char* what) {
  std::size_t used = 0;
  const long v = std::stol(s, &used);
  if (used != s.size() || v < 0)
    throw std::invalid_argument(std::string("bad ") + what + " '" + s + "'");
  return v;
}

//! Next header token of a PPM, skipping whitespace and # comments.
std::string token(std::istream& in) {
  std::string t;
  int c;
  while ((c = in.get()) != EOF) {
    if (c == '#') {
      while ((c = in.get()) != EOF && c != '\n') {
      }
    } else if (std::isspace(c)) {
      if (!t.empty())
        return t;
    } else {
      t += char(c);
    }
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc != 2 && argc != 6) {
      std::cerr << "usage: meshbridge_count_pixels IMAGE.ppm [X Y W H]\n";
      return 2;
    }
    std::ifstream in(argv[1], std::ios::binary);
    if (!in)
      throw std::runtime_error(std::string("cannot open ") + argv[1]);
    if (token(in) != "P6")
      throw std::runtime_error(std::string(argv[1]) + " is not a binary PPM (P6)");
    const long width = parse(token(in), "width"), height = parse(token(in), "height");
    if (parse(token(in), "maxval") != 255)
      throw std::runtime_error("only maxval 255 is supported");
    std::vector<unsigned char> rgb(std::size_t(width * height * 3));
    if (!in.read(reinterpret_cast<char*>(rgb.data()), std::streamsize(rgb.size())))
      throw std::runtime_error(std::string(argv[1]) + " is truncated");
    long x0 = 0, y0 = 0, w = width, h = height;
    if (argc == 6) {
      x0 = parse(argv[2], "x");
      y0 = parse(argv[3], "y");
      w = parse(argv[4], "width");
      h = parse(argv[5], "height");
      if (x0 + w > width || y0 + h > height)
        throw std::invalid_argument("rectangle lies outside the " + std::to_string(width) + "x" +
                                    std::to_string(height) + " image");
    }
    long red = 0, green = 0, violet = 0, selection = 0, background = 0, grey = 0;
    for (long y = y0; y < y0 + h; ++y) {
      for (long x = x0; x < x0 + w; ++x) {
        const unsigned char* p = &rgb[std::size_t((y * width + x) * 3)];
        red += (p[0] >= 120 && p[1] <= 60 && p[2] <= 60) ? 1 : 0;
        green += (p[1] >= 120 && p[0] <= 60 && p[2] <= 60) ? 1 : 0;
        violet += (p[2] >= 100 && p[1] <= 50 && 10 * p[0] >= 3 * p[2] && 10 * p[0] <= 8 * p[2] &&
                   p[0] >= p[1] + 40)
                      ? 1
                      : 0;
        const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
        const bool back =
            std::abs(p[0] - p[1]) <= 2 && ((p[2] > p[0] && 10 * p[2] >= 17 * p[0]) || hi <= 8);
        background += back ? 1 : 0;
        selection += (p[0] >= p[1] + 30 && std::abs(p[1] - p[2]) <= 12 && p[1] > 60) ? 1 : 0;
        grey += (hi - lo <= 12 && hi >= 40) ? 1 : 0;
      }
    }
    std::cout << "width=" << width << "\nheight=" << height << "\npixels=" << w * h
              << "\nred=" << red << "\ngreen=" << green << "\nviolet=" << violet
              << "\nselection=" << selection << "\nbackground=" << background << "\ngrey=" << grey
              << "\nmodel=" << w * h - background << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "meshbridge_count_pixels: " << e.what() << '\n';
    return 1;
  }
}
