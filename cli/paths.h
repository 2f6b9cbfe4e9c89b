// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Checks of the paths a command was given, made before any work, so that a mistake is told at
// once, naming the path and the cause (a missing folder, a permission the OS refuses with its
// reason), instead of after a long repair or in a library's words.

#include <string>

namespace meshbridge::cli {

//! The folder a path's file lives in: "" for "a.obj" becomes ".", "/a.obj" becomes "/".
std::string folder_of(const std::string& path);

//! The last part of a path: "a/b/c.obj" gives "c.obj".
std::string file_name_of(const std::string& path);

//! True when `path` ends in ".png" (any case).
bool ends_with_png(std::string path);

//! Throws ReadError naming `path` when it cannot be read: "the folder 'D' does not exist",
//! "no such file", "it is a folder", or the OS reason (e.g. "Permission denied"). Other
//! problems (format, content) are left to the reader.
void check_readable_file(const std::string& path);

//! True if `path` is the file, pipe or terminal standard output goes to (/dev/stdout, or the file
//! stdout is redirected into).
bool is_standard_output(const std::string& path);

//! Throws WriteError naming `path` when a file cannot be created there: its folder does not
//! exist or is not a folder, creating a file in it fails (the OS reason; tried with a probe
//! file that is removed at once), or `path` is a folder. An existing device or pipe (/dev/stdout,
//! a FIFO) only has to be writable: it is written in place.
void check_writable_file(const std::string& path);

}  // namespace meshbridge::cli
