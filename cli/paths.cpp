// SPDX-License-Identifier: GPL-3.0-or-later
#include "paths.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace meshbridge::cli {

namespace {

// stat() that reports errno; true when it succeeded.
bool stat_path(const std::string& path, struct stat& info, int& error) {
  if (::stat(path.c_str(), &info) == 0)
    return true;
  error = errno;
  return false;
}

// The nearest missing folder on the way to `folder` ("a/b/c" with only "a" present: "a/b").
std::string first_missing(const std::string& folder) {
  std::string missing = folder;
  for (;;) {
    const std::string parent = folder_of(missing);
    struct stat info;
    if (parent == missing || ::stat(parent.c_str(), &info) == 0)
      return missing;
    missing = parent;
  }
}

}  // namespace

bool ends_with_png(std::string path) {
  for (auto& ch : path)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".png") == 0;
}

std::string folder_of(const std::string& path) {
  std::string trimmed = path;
  while (trimmed.size() > 1 && trimmed.back() == '/')
    trimmed.pop_back();
  const auto slash = trimmed.find_last_of('/');
  if (slash == std::string::npos)
    return ".";
  if (slash == 0)
    return "/";
  return trimmed.substr(0, slash);
}

std::string file_name_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void check_readable_file(const std::string& path) {
  struct stat info;
  int error = 0;
  if (!stat_path(path, info, error)) {
    if (error == ENOENT) {
      const std::string folder = folder_of(path);
      struct stat folder_info;
      if (::stat(folder.c_str(), &folder_info) != 0 && errno == ENOENT) {
        throw ReadError(path + ": cannot read: the folder '" + first_missing(folder) +
                        "' does not exist");
      }
      throw ReadError(path + ": cannot read: no such file");
    }
    throw ReadError(path + ": cannot read (" + std::strerror(error) + ")");
  }
  if (S_ISDIR(info.st_mode))
    throw ReadError(path + ": cannot read: it is a folder, not a mesh file");
  if (::access(path.c_str(), R_OK) != 0)
    throw ReadError(path + ": cannot read (" + std::strerror(errno) + ")");
}

bool is_standard_output(const std::string& path) {
  struct stat file, output;
  return ::stat(path.c_str(), &file) == 0 && ::fstat(STDOUT_FILENO, &output) == 0 &&
         file.st_dev == output.st_dev && file.st_ino == output.st_ino;
}

void check_writable_file(const std::string& path) {
  struct stat info;
  int error = 0;
  if (written_in_place(path)) {
    // A device or pipe (/dev/stdout, a FIFO) is written in place: it only has to take writing.
    if (::access(path.c_str(), W_OK) != 0)
      throw WriteError(path + ": cannot write (" + std::strerror(errno) + ")");
    return;
  }
  const std::string folder = folder_of(replaced_file(path));
  if (!stat_path(folder, info, error)) {
    if (error == ENOENT) {
      throw WriteError(path + ": cannot write: the folder '" + first_missing(folder) +
                       "' does not exist");
    }
    throw WriteError(path + ": cannot write into the folder '" + folder + "' (" +
                     std::strerror(error) + ")");
  }
  if (!S_ISDIR(info.st_mode))
    throw WriteError(path + ": cannot write: '" + folder + "' is not a folder");
  if (stat_path(path, info, error) && S_ISDIR(info.st_mode))
    throw WriteError(path + ": cannot write: it is a folder");
  // The file is replaced by renaming a new one over it, which the folder's permission allows
  // even when the file's own does not: refuse a file this user may not write, as a shell
  // redirection would.
  if (stat_path(replaced_file(path), info, error) &&
      ::access(replaced_file(path).c_str(), W_OK) != 0)
    throw WriteError(path + ": cannot write (" + std::strerror(errno) + "): the file is read-only");
  // Creating a file is the test: access() lets root pass where creating still fails (/proc).
  std::string probe = folder + "/.meshbridge-probe-XXXXXX";
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) {
    throw WriteError(path + ": cannot write into the folder '" + folder + "' (" +
                     std::strerror(errno) + ")");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace meshbridge::cli
