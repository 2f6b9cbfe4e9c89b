// SPDX-License-Identifier: GPL-3.0-or-later
// The batch log: a rerun skips a file only when it was done with the same options from the
// same input and its output is there; failed files and changed ones are done again.
#include "meshbridge/batch_log.h"
#include "meshbridge/batch_warnings.h"
#include "meshbridge/file_job.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace meshbridge {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = MESHBRIDGE_MODELS_DIR;

class BatchLog : public ::testing::Test {
 protected:
  void SetUp() override {
    char dir_template[] = "/tmp/meshbridge_batch_log_XXXXXX";
    ASSERT_NE(mkdtemp(dir_template), nullptr);
    root_ = dir_template;
    fs::copy_file(kModels / "twocubes.obj", root_ / "twocubes.obj");
    job_ = {(root_ / "twocubes.obj").string(), (root_ / "out" / "twocubes.obj").string(),
            "twocubes.obj", "twocubes.obj"};
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
  FileJob job_;
};

TEST_F(BatchLog, done_with_the_same_options_and_input_is_skipped_anything_else_redone) {
  FileJobOptions options;
  const FileJobResult result = run_file_job(job_, options);
  ASSERT_EQ(result.status, FileStatus::repaired);
  const std::string line = batch_log_line(result.record, job_, options);
  EXPECT_EQ(record_of_log_line(line), result.record);
  EXPECT_EQ(file_of_log_line(line), "twocubes.obj");
  std::string why;
  EXPECT_TRUE(is_done_in_log(line, job_, options, &why)) << why;

  FileJobOptions filling = options;
  filling.repair.fill_holes.max_edges = 32;
  EXPECT_FALSE(is_done_in_log(line, job_, filling, &why));
  EXPECT_EQ(why, "the options changed");
  FileJobOptions to_3mf = options;
  to_3mf.format = "3MF";
  EXPECT_NE(batch_options_text(to_3mf), batch_options_text(options));
  EXPECT_EQ(batch_options_text(to_3mf).rfind("format=3mf weld=auto ", 0), 0u);

  fs::last_write_time(job_.input, fs::last_write_time(job_.input) + std::chrono::seconds(5));
  EXPECT_FALSE(is_done_in_log(line, job_, options, &why));
  EXPECT_EQ(why, "the input changed");

  const std::string again = batch_log_line(result.record, job_, options);
  fs::remove(job_.output);
  EXPECT_FALSE(is_done_in_log(again, job_, options, &why));
  EXPECT_EQ(why, "the output is missing");
}

TEST_F(BatchLog, a_failed_file_is_always_retried) {
  std::ofstream(job_.input) << "not a mesh\n";
  const FileJobResult failed = run_file_job(job_);
  ASSERT_EQ(failed.status, FileStatus::failed);
  std::string why;
  EXPECT_FALSE(is_done_in_log(batch_log_line(failed.record, job_, {}), job_, {}, &why));
  EXPECT_EQ(why, "its last run ended failed");
}

TEST_F(BatchLog, read_keeps_the_last_line_of_each_file_and_ignores_a_cut_last_line) {
  const std::string path = (root_ / "log.jsonl").string();
  const FileJobResult result = run_file_job(job_);
  const std::string line = batch_log_line(result.record, job_, {});
  write_batch_log(path, {line});
  std::ofstream(path, std::ios::app) << "{\"file\":\"cut";  // a run killed while writing
  const auto lines = read_batch_log(path);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines.at("twocubes.obj"), line);
  std::ofstream(path) << "not json\n";
  EXPECT_THROW(read_batch_log(path), std::runtime_error);
  EXPECT_TRUE(read_batch_log((root_ / "none.jsonl").string()).empty());
}

TEST(BatchWarnings, harmless_kinds_counted_lost_data_per_file) {
  EXPECT_EQ(harmless_warning_kind("output a.stl: ASCII STL solid names, on 1 solid: not written "
                                  "(MeshBridge reads past them)"),
            "ASCII STL solid names not written (MeshBridge reads past them)");
  EXPECT_NE(harmless_warning_kind("output a.3mf: positions of 3 vertices rounded to 32-bit "
                                  "floats: 3MF holds no more"),
            "");
  EXPECT_EQ(harmless_warning_kind("output a.stl: 4 texture coordinates (vt) not written: "
                                  "MeshBridge writes neither"),
            "");
  EXPECT_EQ(harmless_warning_kind("output a.stl: vertex colours not written: STL holds none"), "");
}

}  // namespace
}  // namespace meshbridge
