// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small software rasterizer for the snapshot: flat-shaded triangles into a QImage with a depth
// buffer, and thick lines and dots drawn on top only where nothing nearer covers them. No
// antialiasing, so every defect pixel has exactly its colour and can be counted.

#include <QColor>
#include <QImage>

#include <vector>

namespace meshbridge::cli {

//! A point on the canvas: pixel coordinates (x right, y down) and depth (larger = nearer).
struct CanvasPoint {
  double x = 0, y = 0, depth = 0;
};

class ZBufferCanvas {
 public:
  //! A `width` x `height` canvas filled with `background`, every depth at -infinity.
  //! \throw std::bad_alloc when the image cannot be allocated
  ZBufferCanvas(int width, int height, const QColor& background);

  //! Fills the triangle where it is nearer than what is there. A triangle that covers no pixel
  //! centre (smaller than a pixel) still sets the pixel under its centroid, so a dense mesh
  //! looks like its surface, not like a sieve.
  void fill_triangle(const CanvasPoint& a, const CanvasPoint& b, const CanvasPoint& c, QRgb color);

  //! Draws a line `width` pixels thick in `visible` where it is not behind the surface (within
  //! `tolerance` in depth), and 1 pixel thick in `hidden` where it is (unless `hidden` is fully
  //! transparent). Lines never write depth, so later lines are not hidden by earlier ones.
  //! `opacity` below 1 mixes `visible` with what is under it (a tint instead of a colour).
  void draw_line(const CanvasPoint& a, const CanvasPoint& b, double width, QRgb visible,
                 QRgb hidden, double tolerance, double opacity = 1);
  //! A filled disc of `radius` pixels, where its centre is not behind the surface.
  void draw_dot(const CanvasPoint& centre, double radius, QRgb color, double tolerance);

  //! From now on fill_triangle also keeps the farthest depth of every pixel (at +infinity where
  //! nothing is), for opposite().
  void keep_farthest();
  //! The canvas seen from the opposite side of the same orthographic camera: mirrored left to
  //! right (pixel x to width - 1 - x; a point at x to width - x), the farthest depths kept since
  //! keep_farthest(), negated, as its depths, every pixel they cover `color`, the rest the
  //! background. What fill_triangle would have drawn of the mirrored triangles in one colour.
  //! \pre keep_farthest() was called before the triangles were filled
  ZBufferCanvas opposite(QRgb color) const;

  QImage& image() { return image_; }

 private:
  void stamp(double x, double y, double radius, QRgb color, double opacity = 1);
  bool visible(double x, double y, double depth, double tolerance) const;

  QImage image_;
  std::vector<float> depth_;
  std::vector<float> farthest_;  //!< empty unless keep_farthest()
  QRgb background_;
  int width_, height_;
};

}  // namespace meshbridge::cli
