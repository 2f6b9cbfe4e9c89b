// SPDX-License-Identifier: GPL-3.0-or-later
// The per-face-vertex weld (core/src/io/repeated_vertices.cpp) against a reference written here
// (a std::map from position to its first vertex), and the text readers' numbers against
// std::from_chars (core/src/io/parse_numbers.h's fast path).

#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"

#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cstring>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace meshbridge {
namespace {

class SoupWeld : public test_support::ScratchFolderTest {
 public:
  SoupWeld() : ScratchFolderTest("soup_weld_exact") {}
};

TEST_F(SoupWeld, welded_vertices_are_numbered_in_first_appearance_exactly) {
  // Checkerboard cubes with their faces shuffled, written per face vertex; some positions
  // moved to -0 in one coordinate on some of their corners (one position with +0).
  const Soup shuffled = test_support::shuffled(models::checkerboard_cubes(4), 11);
  std::ostringstream obj;
  obj.precision(17);
  std::vector<Point> file_positions;
  std::size_t negative_zeros = 0;
  for (std::size_t f = 0; f < shuffled.num_faces(); ++f) {
    for (Index v : shuffled.polygon(f)) {
      Point p = shuffled.positions[v];
      file_positions.push_back(p);
      obj << "v";
      for (int k = 0; k < 3; ++k) {
        if (p[k] == 0 && file_positions.size() % 3 == 0) {
          obj << " -0";
          ++negative_zeros;
        } else {
          obj << " " << p[k];
        }
      }
      obj << "\n";
    }
    obj << "f";
    const std::size_t arity = shuffled.arity(f);
    for (std::size_t i = 0; i < arity; ++i)
      obj << " " << file_positions.size() - arity + i + 1;
    obj << "\n";
  }
  ASSERT_GT(negative_zeros, 10u);
  // The reference: each corner's position, its vertex the first corner at that position.
  std::map<std::tuple<double, double, double>, Index> first;
  std::vector<Point> expected_positions;
  std::vector<Index> expected_corners;
  for (const Point& p : file_positions) {
    const auto key = std::make_tuple(p[0] + 0.0, p[1] + 0.0, p[2] + 0.0);  // -0 is +0
    const auto [at, added] = first.emplace(key, static_cast<Index>(expected_positions.size()));
    if (added)
      expected_positions.push_back(p);
    expected_corners.push_back(at->second);
  }
  ReadInfo info;
  const Soup read = read_soup(write("shuffled.obj", obj.str()), &info);
  EXPECT_EQ(info.vertices_welded_by_position, file_positions.size() - expected_positions.size());
  ASSERT_EQ(read.num_vertices(), expected_positions.size());
  EXPECT_EQ(read.corner_vertices, expected_corners);
  std::size_t differing = 0;
  for (std::size_t v = 0; v < read.num_vertices(); ++v)
    differing += read.positions[v] != expected_positions[v];
  EXPECT_EQ(differing, 0u);
  EXPECT_EQ(read.num_faces(), shuffled.num_faces());
}

TEST_F(SoupWeld, numbers_read_as_from_chars_reads_them) {
  // Short decimals (the fast path), long ones, exponents, signs, 2^53 and its neighbours, and
  // random digit strings of 1 to 21 digits with a point anywhere.
  std::vector<std::string> texts = {"0",
                                    "-0",
                                    "0.1",
                                    "-0.30000000000000004",
                                    "9007199254740992",
                                    "9007199254740993",
                                    "9007199254740993.5",
                                    "123456789012345678",
                                    "1234567890123456789",
                                    "12345678901234567890",
                                    "0.0000000000000000000001",
                                    "1.0000000000000000000000001",
                                    "1e3",
                                    "2.5E-3",
                                    "+7.25",
                                    "000123.4500",
                                    "1.7976931348623157e308",
                                    "4.9e-324"};
  std::mt19937 random(5);
  for (int i = 0; i < 3000; ++i) {
    std::string digits;
    const int n = 1 + static_cast<int>(random() % 21);
    for (int k = 0; k < n; ++k)
      digits.push_back(static_cast<char>('0' + random() % 10));
    const int point = static_cast<int>(random() % (n + 1));
    if (point > 0 && point < n)
      digits.insert(static_cast<std::size_t>(point), ".");
    texts.push_back((random() % 2 ? "-" : "") + digits);
  }
  while (texts.size() % 3 != 0)
    texts.push_back("1");
  std::string obj;
  for (std::size_t i = 0; i < texts.size(); i += 3)
    obj += "v " + texts[i] + " " + texts[i + 1] + " " + texts[i + 2] + "\n";
  obj += "f 1 2 3\n";
  const Soup read = read_soup(write("numbers.obj", obj));
  ASSERT_EQ(read.num_vertices(), texts.size() / 3);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const std::string& t = texts[i];
    double expected = 0;
    const char* first = t.data() + (t[0] == '+');
    std::from_chars(first, t.data() + t.size(), expected);
    const double got = read.positions[i / 3][i % 3];
    if (std::memcmp(&got, &expected, sizeof got) != 0) {
      ADD_FAILURE() << t << " read as " << got << ", from_chars gives " << expected;
      ++differing;
    }
  }
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace meshbridge
