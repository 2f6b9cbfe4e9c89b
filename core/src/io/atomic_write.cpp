// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/atomic_write.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <random>

namespace meshbridge {

bool written_in_place(const std::string& path) {
  if (path.rfind("/dev/", 0) == 0)
    return true;
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode);
}

std::string replaced_file(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0 || !S_ISLNK(info.st_mode))
    return path;
  char* resolved = ::realpath(path.c_str(), nullptr);
  if (resolved == nullptr)  // a dangling link: the rename replaces the link itself
    return path;
  std::string target(resolved);
  std::free(resolved);
  return target;
}

}  // namespace meshbridge

namespace meshbridge::detail {

namespace {

std::atomic<unsigned long> call_counter{0};

std::string extension_of(const std::string& name) {
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? std::string() : name.substr(dot);
}

// Creates a fresh temporary file beside `path` (O_EXCL: never someone else's) and returns its
// name; the file descriptor is closed again, the name is ours until rename or removal.
std::string create_temporary(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  static thread_local std::minstd_rand random(static_cast<unsigned>(
      std::chrono::steady_clock::now().time_since_epoch().count() ^ ::getpid()));
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string temporary = dir + "." + name + "." + std::to_string(::getpid()) + "." +
                                  std::to_string(call_counter++) + "." +
                                  std::to_string(random() % 1000000) + ".tmp" + extension_of(name);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return temporary;
    }
    if (errno != EEXIST)
      throw WriteError(path + ": cannot create a file in its directory (" + std::strerror(errno) +
                       ")");
  }
  throw WriteError(path + ": cannot find a free temporary name beside it");
}

}  // namespace

AtomicOutput::AtomicOutput(std::string temporary_path, std::string target)
    : temporary_(std::move(temporary_path)), target_(std::move(target)) {}

AtomicOutput::~AtomicOutput() {
  if (file_ != nullptr)
    std::fclose(file_);
}

std::FILE* AtomicOutput::file() {
  if (file_ == nullptr) {
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (file_ == nullptr)
      throw WriteError(target_ + ": cannot write (" + std::strerror(errno) + ")");
    std::setvbuf(file_, nullptr, _IOFBF, 1 << 20);
  }
  return file_;
}

void AtomicOutput::write(const void* bytes, std::size_t size) {
  if (size > 0 && std::fwrite(bytes, 1, size, file()) != size)
    throw WriteError(target_ + ": write failed (" + std::strerror(errno) + ")");
}

void AtomicOutput::close() {
  if (file_ == nullptr)
    return;
  const bool flushed = std::fflush(file_) == 0 && !std::ferror(file_);
  const int flush_errno = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed)
    throw WriteError(target_ + ": write failed (" + std::strerror(flush_errno) + ")");
}

void write_atomically(const std::string& path, const std::function<void(AtomicOutput&)>& fill) {
  if (written_in_place(path)) {  // never replace a device node or /dev/stdout with a file
    AtomicOutput output(path, path);
    fill(output);
    output.close();
    return;
  }
  const std::string target = replaced_file(path);  // a symbolic link stays one
  const std::string temporary = create_temporary(target);
  try {
    AtomicOutput output(temporary, path);
    fill(output);
    output.close();
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  // The file replaced keeps its permissions (and, where allowed, its owner), as a shell
  // redirection into it would: a 0600 output does not become world-readable.
  struct stat replaced {};
  if (::stat(target.c_str(), &replaced) == 0 && S_ISREG(replaced.st_mode)) {
    if (::chown(temporary.c_str(), replaced.st_uid, replaced.st_gid) != 0)
      (void)::chown(temporary.c_str(), static_cast<uid_t>(-1), replaced.st_gid);  // group only
    (void)::chmod(temporary.c_str(), replaced.st_mode & 07777);
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw WriteError(path + ": cannot move the written file into place (" + reason + ")");
  }
}

}  // namespace meshbridge::detail
