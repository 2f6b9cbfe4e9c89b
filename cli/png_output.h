// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writing the snapshot PNGs: Qt on the "offscreen" platform (no display needed) and an atomic
// PNG write that names the cause of a failure.

#include <QGuiApplication>
#include <QImage>

#include <memory>
#include <string>

namespace meshbridge::cli {

//! Writes `image` as PNG under a hidden temporary name beside `path` and renames it into place,
//! so on any error the previous file at `path` is untouched and nothing half-written is left.
//! \throw WriteError naming the path and the reason (the OS reason when there is one)
void write_png_atomically(const std::string& path, const QImage& image);

//! While alive: a QGuiApplication (fonts need one) on the "offscreen" platform unless the user
//! chose one through QT_QPA_PLATFORM, with Qt's debug output and warnings dropped (offscreen
//! they are chatter such as "QStandardPaths: XDG_RUNTIME_DIR not set"); Qt's critical and fatal
//! messages still reach stderr, prefixed "meshbridge: Qt: ". One at a time.
class OffscreenQt {
 public:
  OffscreenQt();
  ~OffscreenQt();
  OffscreenQt(const OffscreenQt&) = delete;
  OffscreenQt& operator=(const OffscreenQt&) = delete;

 private:
  QtMessageHandler previous_;
  std::unique_ptr<QGuiApplication> application_;
};

}  // namespace meshbridge::cli
