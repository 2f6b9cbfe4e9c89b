// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one way MeshBridge writes a file: under a unique temporary name beside the target, renamed
// over the target only when everything was written. A target that is a device or a pipe
// (/dev/null, /dev/stdout, a FIFO) is written in place instead: renaming over it would replace
// the device node with a file. A symbolic link stays one: the file it points to is replaced.

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace meshbridge::detail {

//! The temporary file a write_atomically callback fills. Either write through `write()`/`file()`
//! (a buffered stdio stream, opened on first use) or, for a library that insists on a file name
//! (lib3mf), write to `temporary_path()` yourself and leave the stream alone.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::string temporary_path, std::string target);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::string& temporary_path() const { return temporary_; }
  const std::string& target() const { return target_; }  //!< for error messages
  //! The stream on the temporary file (1 MiB buffer). \throw WriteError if it cannot be opened
  std::FILE* file();
  //! Appends bytes. \throw WriteError (disk full, I/O error) naming the target
  void write(const void* bytes, std::size_t size);
  void write(std::string_view text) { write(text.data(), text.size()); }
  //! Flushes and closes the stream if one was opened. \throw WriteError on a failed flush
  void close();

 private:
  std::string temporary_;
  std::string target_;
  std::FILE* file_ = nullptr;
};

//! Writes `path` atomically: `fill` writes the whole content into an AtomicOutput whose
//! temporary file is `.<name>.<pid>.<counter>.<random>.tmp.<ext>` in the target's directory
//! (unique per process and call, created with O_EXCL), then it is renamed over `path`.
//! If `fill` throws or any step fails, the temporary file is removed and `path` is untouched.
//! A `path` that written_in_place() is written directly, with no temporary file (what reached a
//! pipe before a failure stays there); a symbolic link's target (replaced_file()) is replaced.
//! \throw WriteError naming `path` and the reason (whatever `fill` throws is passed on)
void write_atomically(const std::string& path, const std::function<void(AtomicOutput&)>& fill);

}  // namespace meshbridge::detail
