// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/validate.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/repair.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using namespace meshbridge;

namespace {

using test_support::triangle;

std::string error_of(const Soup& soup) {
  try {
    validate_soup(soup);
  } catch (const InvalidSoupError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(ValidateSoup, accepts_a_triangle) {
  EXPECT_NO_THROW(validate_soup(triangle()));
}

TEST(ValidateSoup, index_out_of_range_names_face_corner_and_index) {
  Soup soup = triangle();
  soup.add_polygon({0, 2, 7});
  EXPECT_EQ(error_of(soup),
            "face 1, corner 2: vertex index 7 is out of range (the soup has 3 vertices)");
}

TEST(ValidateSoup, arity_below_three_names_the_face) {
  Soup soup = triangle();
  soup.add_polygon({0, 1});
  EXPECT_EQ(error_of(soup), "face 1 has 2 corner(s); a polygon needs at least 3");
  Soup empty_polygon = triangle();
  empty_polygon.add_polygon(std::vector<Index>{});
  EXPECT_EQ(error_of(empty_polygon), "face 1 has 0 corner(s); a polygon needs at least 3");
}

TEST(ValidateSoup, non_finite_coordinate_names_the_vertex) {
  Soup soup = triangle();
  soup.positions[1][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of(soup).find("vertex 1 has a non-finite coordinate"), std::string::npos);
  soup.positions[1][2] = std::numeric_limits<double>::infinity();
  EXPECT_NE(error_of(soup).find("vertex 1 has a non-finite coordinate"), std::string::npos);
}

TEST(ValidateSoup, broken_offsets_are_rejected) {
  Soup soup = triangle();
  soup.face_begin.back() = 2;
  EXPECT_EQ(error_of(soup), "soup: face offsets do not cover the corner list");
}

TEST(ValidateSoup, offsets_that_decrease_are_named_not_read_past) {
  Soup soup = triangle();
  soup.add_polygon({0, 1, 2});  // offsets {0, 3, 6}
  soup.face_begin[1] = 7;       // face 0 would span 7 of the 6 corners
  EXPECT_EQ(error_of(soup),
            "face 0 has corners past the end of the corner list (face offsets must not decrease)");
  soup.add_polygon({0, 1, 2});
  soup.face_begin = {0, 4, 3, 9};  // face 0 has 4 corners, face 1 ends before it begins
  EXPECT_EQ(error_of(soup), "face 1 has a negative corner count");
}

TEST(ValidateSoup, repeated_vertex_is_accepted_and_reported) {
  Soup soup = triangle();
  soup.add_polygon({0, 0, 1});
  EXPECT_NO_THROW(validate_soup(soup));
  const DefectReport report = detect_defects(soup);
  EXPECT_EQ(report.degenerate_faces, std::vector<Index>{1});
  EXPECT_EQ(report.faces_set_aside, std::vector<Index>{1});
}

TEST(ValidateSoup, every_entry_point_checks) {
  Soup soup = triangle();
  soup.add_polygon({0, 1, 9});
  EXPECT_THROW(detect_defects(soup), InvalidSoupError);
  EXPECT_THROW(repair(soup), InvalidSoupError);
}
