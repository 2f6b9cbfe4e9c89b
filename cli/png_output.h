// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Qt for the snapshot PNGs, inside the meshbridge_pictures module: Qt on the "offscreen" platform
// (no display needed) and PNG encoding in memory (the executable writes the bytes atomically).

#include <QByteArray>
#include <QGuiApplication>
#include <QImage>

#include <memory>
#include <stdexcept>

namespace meshbridge::cli {

//! Qt could not encode an image as PNG.
class PngEncodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! `image` as the bytes of a PNG file.
//! \throw PngEncodeError "cannot encode the PNG (Qt's reason)"
QByteArray encode_png(const QImage& image);

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
