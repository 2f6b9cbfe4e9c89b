// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A test fixture with a private folder under /tmp for the files a test writes, removed with
// everything in it after the test.

#include <gtest/gtest.h>

#include <stdlib.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace meshbridge::test_support {

class ScratchFolderTest : public ::testing::Test {
 protected:
  //! The folder is /tmp/meshbridge_<prefix>_XXXXXX (mkdtemp).
  explicit ScratchFolderTest(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    std::string pattern = "/tmp/meshbridge_" + prefix_ + "_XXXXXX";
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }

  //! The path of `name` in the folder.
  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  //! Writes `bytes` to `name` in the folder, as they are; returns its path.
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = path(name);
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p;
  }

  std::string dir_;  //!< the folder (no trailing '/')

 private:
  std::string prefix_;
};

}  // namespace meshbridge::test_support
