// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A whole file as one read-only byte range (memory-mapped), for the readers.

#include <cstddef>
#include <string>
#include <string_view>

namespace meshbridge::detail {

//! The bytes of a regular file, mapped read-only for the object's lifetime.
//! Precondition: none; the constructor checks everything.
//! \throw ReadError naming `path`: missing or unreadable, a directory, empty, or not mappable
class MappedFile {
 public:
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const char* data() const { return data_; }
  const char* end() const { return data_ + size_; }
  std::size_t size() const { return size_; }  //!< bytes, > 0
  std::string_view view() const { return {data_, size_}; }
  const std::string& path() const { return path_; }

  //! Hands the pages wholly before `upto` back to the kernel (they stay readable: touching them
  //! again reads them back from the page cache). A reader that streams calls this every few
  //! megabytes, so the map adds only a window to the peak memory, not the whole file.
  void release_before(const char* upto) const { release_between(data_, upto); }
  //! The same for the pages wholly inside [from, upto): for readers that read parts side by
  //! side, each releasing only its own.
  void release_between(const char* from, const char* upto) const;
  //! Maps the pages touching [from, upto) in one system call (MADV_POPULATE_READ), so that a
  //! reader streaming through them takes no page fault every few pages. Only a hint: ignored
  //! where the kernel does not know it (before Linux 5.14).
  void prefault_between(const char* from, const char* upto) const;

 private:
  std::string path_;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace meshbridge::detail
