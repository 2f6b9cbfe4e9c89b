// SPDX-License-Identifier: GPL-3.0-or-later
// The monotone invariant (DESIGN 8a, no new defects) on every real-world file the repository
// ships (tests/data/realworld, tests/data/realworld2) and, where it is beside the clone, on
// ../shared/data/realworld*: with default options, the repaired mesh has no more boundary edges
// than the input (one more allowed per singular edge with an odd number of faces), no singular
// element, no more non-orientable components or inconsistently oriented edges, and no side cut
// to stay manifold.
#include "meshbridge/io.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#ifndef MESHBRIDGE_REALWORLD_DIR
#error "define MESHBRIDGE_REALWORLD_DIR as the path of tests/data/realworld"
#endif

using namespace meshbridge;
namespace fs = std::filesystem;

namespace {

bool is_mesh(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".3mf";
}

std::vector<fs::path> corpus() {
  const fs::path shipped = fs::path(MESHBRIDGE_REALWORLD_DIR).parent_path();
  std::vector<fs::path> folders{shipped / "realworld", shipped / "realworld2"};
  // ../shared/data beside the clone (the developers' and CI's machines have it).
  const fs::path shared = shipped.parent_path().parent_path().parent_path() / "shared" / "data";
  std::error_code error;
  if (fs::is_directory(shared, error)) {
    for (const auto& entry : fs::directory_iterator(shared, error)) {
      if (entry.is_directory() && entry.path().filename().string().rfind("realworld", 0) == 0)
        folders.push_back(entry.path());
    }
  }
  std::vector<fs::path> files;
  for (const fs::path& folder : folders) {
    if (!fs::is_directory(folder, error))
      continue;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      if (entry.is_regular_file() && is_mesh(entry.path()))
        files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST(Corpus, repair_never_leaves_a_real_file_worse) {
  const std::vector<fs::path> files = corpus();
  ASSERT_GE(files.size(), 13u);  // the 8 + 5 files the repository ships at least
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    ReadInfo info;
    const Soup soup = read_soup(file.string(), &info);
    RepairOptions options;
    options.close_gaps.float_coordinates = info.float_coordinates;
    const RepairResult r = repair(soup, options);
    const DefectReport& before = r.report.before;
    const DefectReport& after = r.report.after;
    std::size_t odd = 0;
    for (const SingularEdge& e : before.singular_edges)
      odd += e.contenders % 2;
    EXPECT_LE(after.boundary_edges.size(), before.boundary_edges.size() + odd);
    EXPECT_EQ(after.singular_edges.size(), 0u);
    EXPECT_EQ(after.num_singular_vertices(), 0u);
    EXPECT_LE(after.num_nonorientable_components, before.num_nonorientable_components);
    EXPECT_LE(after.inconsistent_edges.size(), before.inconsistent_edges.size());
    EXPECT_EQ(r.report.sides_cut_to_stay_manifold, 0u);
    EXPECT_EQ(r.report.faces_in, soup.num_faces());
  }
}

// Check predicts repair (DESIGN 8a): where preview_repair() says repair changes nothing, the
// repaired mesh is the input, polygon for polygon; where it says repair changes something, the
// repair's own report says so too. check_soup() says the same as the two calls.
TEST(Corpus, check_predicts_repair_on_every_real_file) {
  std::size_t unchanged = 0;
  for (const fs::path& file : corpus()) {
    SCOPED_TRACE(file.string());
    ReadInfo info;
    const Soup soup = read_soup(file.string(), &info);
    RepairOptions options;
    options.close_gaps.float_coordinates = info.float_coordinates;
    OrientationPreview orientation;
    const DefectReport before = detect_defects(soup, &orientation);
    const RepairPreview preview = preview_repair(soup, before, orientation, options);
    const RepairResult r = repair(soup, options);
    EXPECT_EQ(preview.changes, repair_changes_input(r.report));
    EXPECT_EQ(preview.report.vertices_split, r.report.vertices_split);
    EXPECT_EQ(preview.report.faces_flipped, r.report.faces_flipped);
    const SoupCheck checked = check_soup(soup, options);  // what `meshbridge check` runs
    EXPECT_EQ(to_text(checked.report), to_text(before));
    EXPECT_EQ(to_text(checked.preview), to_text(preview));
    if (preview.changes)
      continue;
    ++unchanged;
    EXPECT_EQ(r.mesh.soup.positions, soup.positions);
    EXPECT_EQ(r.mesh.soup.corner_vertices, soup.corner_vertices);
  }
  EXPECT_GE(unchanged, 1u);  // some real files are left as they are
}
