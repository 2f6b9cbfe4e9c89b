// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The warnings of `batch` on stderr. What a file lost (texture coordinates, normals, groups,
// colours, a unit, faces a reader split or set aside) stays one line per file; harmless kinds
// that many files share (STL solid names, 32-bit float rounding, PLY comments) are counted and
// printed once each, with the number of files, when the batch ends. --quiet prints none.

#include <cstddef>
#include <map>
#include <string>

namespace meshbridge::cli {

//! Prints the warnings of a batch's files (meshbridge/batch_warnings.h says which are harmless).
class BatchWarnings {
 public:
  explicit BatchWarnings(bool quiet) : quiet_(quiet) {}
  //! One file's warnings (lines): lost data printed now as
  //! "meshbridge: warning: NAME: LINE", harmless ones counted (once per file and kind).
  void file(const std::string& name, const std::string& lines);
  //! "meshbridge: warning: N file(s): KIND" once per kind counted, in order of first sight.
  void finish();

 private:
  bool quiet_;
  std::map<std::string, std::size_t> files_;  //!< kind -> files it was seen in
  std::map<std::size_t, std::string> order_;  //!< first sight -> kind
};

}  // namespace meshbridge::cli
