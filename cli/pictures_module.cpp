// SPDX-License-Identifier: GPL-3.0-or-later
// The meshbridge_pictures module's entry point (cli/pictures_api.h): draws with Qt, hands back PNG
// bytes. Everything else in the module is hidden (built with -fvisibility=hidden).

#include "pictures_api.h"

#include "defect_snapshot.h"
#include "png_output.h"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <stdexcept>

namespace meshbridge::cli {

namespace {

//! A malloc'ed copy of `text` (null when even that does not fit).
char* copy_of(const char* text) {
  const std::size_t size = std::strlen(text) + 1;
  char* copy = static_cast<char*>(std::malloc(size));
  if (copy != nullptr)
    std::memcpy(copy, text, size);
  return copy;
}

void fail(MeshbridgePictureResult& result, MeshbridgePicturesStatus status, const char* message) {
  result.status = status;
  result.error = copy_of(message);
}

//! Draws `picture`; an automatic view becomes `view` unless that is automatic too.
DefectSnapshot draw(const MeshbridgePictureRequest& picture, const SnapshotView& view) {
  if (picture.soup == nullptr || picture.report == nullptr || picture.options == nullptr)
    throw std::invalid_argument("draw_png: a picture without soup, report or options");
  SnapshotOptions options = *picture.options;
  if (options.view.automatic)
    options.view = view;
  return draw_defect_snapshot(*picture.soup, *picture.report, options, picture.frame_soup,
                              picture.frame_report, picture.crossings);
}

void draw_png(const MeshbridgePictureRequest* pictures, std::size_t count,
              MeshbridgePictureResult* result) {
  *result = MeshbridgePictureResult{};
  try {
    if (pictures == nullptr || count == 0)
      throw std::invalid_argument("draw_png: no picture to draw");
    const OffscreenQt qt;  // fonts for the legends
    DefectSnapshot drawn = draw(pictures[0], SnapshotView::automatic_view());
    const SnapshotView first = drawn.view;
    for (std::size_t i = 1; i < count; ++i)
      drawn = side_by_side(drawn, draw(pictures[i], first));
    const QByteArray png = encode_png(drawn.image);
    result->png = static_cast<unsigned char*>(std::malloc(static_cast<std::size_t>(png.size())));
    if (result->png == nullptr)
      throw std::bad_alloc();
    std::memcpy(result->png, png.constData(), static_cast<std::size_t>(png.size()));
    result->png_size = static_cast<std::size_t>(png.size());
    result->red_pixels = drawn.red_pixels;
    result->green_pixels = drawn.green_pixels;
    result->violet_pixels = drawn.violet_pixels;
    result->legend_drawn = drawn.legend_drawn ? 1 : 0;
    result->view = drawn.view;
    result->status = MESHBRIDGE_PICTURES_OK;
  } catch (const std::bad_alloc&) {
    fail(*result, MESHBRIDGE_PICTURES_OUT_OF_MEMORY, "out of memory");
  } catch (const PngEncodeError& error) {
    fail(*result, MESHBRIDGE_PICTURES_ENCODE_FAILED, error.what());
  } catch (const std::exception& error) {
    fail(*result, MESHBRIDGE_PICTURES_BAD_INPUT, error.what());
  } catch (...) {
    fail(*result, MESHBRIDGE_PICTURES_BAD_INPUT, "unknown error while drawing");
  }
}

void release(MeshbridgePictureResult* result) {
  std::free(result->error);
  std::free(result->png);
  *result = MeshbridgePictureResult{};
}

constexpr MeshbridgePicturesApi kApi = {MESHBRIDGE_PICTURES_ABI, &draw_png, &release};

}  // namespace

}  // namespace meshbridge::cli

extern "C" __attribute__((visibility("default"))) const MeshbridgePicturesApi*
meshbridge_pictures_api(void) {
  return &meshbridge::cli::kApi;
}
