// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/mapped_file.h"

#include "meshbridge/errors.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

namespace meshbridge::detail {

MappedFile::MappedFile(const std::string& path) : path_(path) {
  // O_NONBLOCK: opening a FIFO with no writer returns at once (and is refused below) instead
  // of waiting forever; it changes nothing for a regular file.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0)
    throw ReadError(path + ": cannot open (" + std::strerror(errno) + ")");
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    throw ReadError(path + ": cannot open (" + reason + ")");
  }
  if (S_ISDIR(status.st_mode)) {
    ::close(fd);
    throw ReadError(path + ": is a directory, not a mesh file");
  }
  if (!S_ISREG(status.st_mode)) {
    ::close(fd);
    throw ReadError(path + ": not a regular file (a FIFO, socket or device cannot be mapped)");
  }
  if (status.st_size == 0) {
    ::close(fd);
    throw ReadError(path + ": file is empty");
  }
  size_ = static_cast<std::size_t>(status.st_size);
  void* map = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
  const int map_errno = errno;
  ::close(fd);
  if (map == MAP_FAILED)
    throw ReadError(path + ": cannot map the file (" + std::strerror(map_errno) + ")");
  ::madvise(map, size_, MADV_SEQUENTIAL);
  data_ = static_cast<const char*>(map);
}

void MappedFile::release_between(const char* from, const char* upto) const {
  static const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  if (from < data_)
    from = data_;
  if (upto > data_ + size_)
    upto = data_ + size_;
  const std::size_t first = (static_cast<std::size_t>(from - data_) + page - 1) / page * page;
  const std::size_t last = upto > data_ ? static_cast<std::size_t>(upto - data_) / page * page : 0;
  if (last > first)
    ::madvise(const_cast<char*>(data_) + first, last - first, MADV_DONTNEED);
}

void MappedFile::prefault_between(const char* from, const char* upto) const {
#ifdef MADV_POPULATE_READ
  static const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  if (from < data_)
    from = data_;
  if (upto > data_ + size_)
    upto = data_ + size_;
  if (upto <= from)
    return;
  const std::size_t first = static_cast<std::size_t>(from - data_) / page * page;
  ::madvise(const_cast<char*>(data_) + first, static_cast<std::size_t>(upto - data_) - first,
            MADV_POPULATE_READ);
#else
  (void)from;
  (void)upto;
#endif
}

MappedFile::~MappedFile() {
  if (data_ != nullptr)
    ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace meshbridge::detail
