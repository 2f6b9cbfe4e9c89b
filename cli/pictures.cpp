// SPDX-License-Identifier: GPL-3.0-or-later
#include "pictures.h"

#include "paths.h"
#include "pictures_api.h"

#include "meshbridge/errors.h"
#include "meshbridge/io.h"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <string_view>

#ifndef MESHBRIDGE_PICTURES_FILE
#error "MESHBRIDGE_PICTURES_FILE (the module's file name) is set by cli/CMakeLists.txt"
#endif
#ifndef MESHBRIDGE_PICTURES_INSTALL_DIR
#error \
    "MESHBRIDGE_PICTURES_INSTALL_DIR (the module's folder from bin/) is set by cli/CMakeLists.txt"
#endif

namespace meshbridge::cli {

namespace {

constexpr const char* kUnavailable = "cannot draw pictures: ";

//! The folder of the running executable, symbolic links resolved (/proc/self/exe).
std::string executable_folder() {
  std::string path(4096, '\0');
  const ssize_t length = ::readlink("/proc/self/exe", path.data(), path.size());
  if (length <= 0 || static_cast<std::size_t>(length) >= path.size()) {
    throw PicturesUnavailable(std::string(kUnavailable) +
                              "cannot tell where the meshbridge executable is (/proc/self/exe: " +
                              (length < 0 ? std::strerror(errno) : "name too long") + ")");
  }
  path.resize(static_cast<std::size_t>(length));
  return folder_of(path);
}

//! The folders find_pictures_module looks in, in order.
std::vector<std::string> module_folders() {
  const std::string folder = executable_folder();
  const std::filesystem::path installed =
      std::filesystem::path(folder) / MESHBRIDGE_PICTURES_INSTALL_DIR;
  return {folder, installed.lexically_normal().string()};
}

//! The module's table, loaded on the first call.
const MeshbridgePicturesApi& pictures_api() {
  static const MeshbridgePicturesApi* api = nullptr;
  if (api != nullptr)
    return *api;
  const std::string path = find_pictures_module();
  // Never dlclose()d: Qt's libraries do not unload cleanly, and LeakSanitizer matches its
  // suppressions (tests/cli/lsan_qt_offscreen.supp) against the symbols of loaded code only.
  void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr)
    throw PicturesUnavailable(std::string(kUnavailable) + ::dlerror());
  const auto entry =
      reinterpret_cast<MeshbridgePicturesEntry>(::dlsym(module, MESHBRIDGE_PICTURES_ENTRY));
  if (entry == nullptr) {
    ::dlclose(module);
    throw PicturesUnavailable(std::string(kUnavailable) + path + " has no " +
                              MESHBRIDGE_PICTURES_ENTRY + "()");
  }
  const MeshbridgePicturesApi* table = entry();
  if (table == nullptr || table->abi != MESHBRIDGE_PICTURES_ABI) {
    const std::string abi = table == nullptr ? "none" : std::to_string(table->abi);
    ::dlclose(module);
    throw PicturesUnavailable(std::string(kUnavailable) + path +
                              " belongs to another meshbridge version (pictures ABI " + abi +
                              ", expected " + std::to_string(MESHBRIDGE_PICTURES_ABI) + ")");
  }
  api = table;
  return *api;
}

//! Gives a result's buffers back to the module that allocated them.
class ResultGuard {
 public:
  explicit ResultGuard(const MeshbridgePicturesApi& api) : api_(api) {}
  ~ResultGuard() { api_.release(&result_); }
  ResultGuard(const ResultGuard&) = delete;
  ResultGuard& operator=(const ResultGuard&) = delete;
  MeshbridgePictureResult& result() { return result_; }

 private:
  const MeshbridgePicturesApi& api_;
  MeshbridgePictureResult result_{};
};

}  // namespace

std::string find_pictures_module() {
  std::string tried;
  for (const std::string& folder : module_folders()) {
    const std::string path = folder + "/" + MESHBRIDGE_PICTURES_FILE;
    struct stat info;
    if (::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode))
      return path;
    tried += (tried.empty() ? "" : ", ") + folder;
  }
  throw PicturesUnavailable(std::string(kUnavailable) + "meshbridge_pictures module not found in " +
                            tried + " (looked for " + MESHBRIDGE_PICTURES_FILE + ")");
}

PicturesDrawn write_pictures_png(const std::string& path, const std::vector<Picture>& pictures) {
  const MeshbridgePicturesApi& api = pictures_api();
  std::vector<MeshbridgePictureRequest> requests;
  for (const Picture& picture : pictures) {
    requests.push_back({picture.soup, picture.report, &picture.options, picture.frame_soup,
                        picture.frame_report, picture.crossings});
  }
  ResultGuard guard(api);
  MeshbridgePictureResult& result = guard.result();
  api.draw_png(requests.data(), requests.size(), &result);
  const std::string message = result.error != nullptr ? result.error : "no reason given";
  switch (result.status) {
    case MESHBRIDGE_PICTURES_OK:
      break;
    case MESHBRIDGE_PICTURES_OUT_OF_MEMORY:
      throw std::bad_alloc();
    case MESHBRIDGE_PICTURES_ENCODE_FAILED:
      throw WriteError(path + ": " + message);
    default:
      throw std::runtime_error(message);
  }
  write_bytes_atomically(
      path, std::string_view(reinterpret_cast<const char*>(result.png), result.png_size));
  PicturesDrawn drawn;
  drawn.red_pixels = result.red_pixels;
  drawn.green_pixels = result.green_pixels;
  drawn.violet_pixels = result.violet_pixels;
  drawn.legend_drawn = result.legend_drawn != 0;
  drawn.view = result.view;
  return drawn;
}

}  // namespace meshbridge::cli
