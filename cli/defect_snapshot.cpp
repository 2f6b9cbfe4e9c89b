// SPDX-License-Identifier: GPL-3.0-or-later
#include "defect_snapshot.h"
#include "meshbridge/counted.h"

#include "meshbridge/polygon_triangles.h"
#include "meshbridge/validate.h"

#include "snapshot_frame.h"
#include "snapshot_views.h"
#include "zbuffer_canvas.h"

#include <QColor>
#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QLineF>
#include <QPainter>
#include <QPen>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace meshbridge::cli {

namespace {

const QColor kBackground(255, 255, 255);
const QColor kEdgeColor(192, 192, 192);
const QColor kBoundaryColor(0, 160, 0);
const QColor kSingularColor(220, 0, 0);
//! Self-intersecting faces: the violet of MeshLab's Detect (plugin/crossing_faces.h).
const QColor kCrossingColor(140, 0, 255);
const QColor kLegendColor(0, 0, 0);

//! Light grey for a face whose unit normal makes `cosine` with the light (both sides lit).
QRgb shade(double cosine) {
  const int grey = static_cast<int>(std::lround(95 + 140 * std::min(1.0, std::abs(cosine))));
  return qRgb(grey, grey, grey);
}

//! Violet for a self-intersecting face, shaded like shade() but never darker than 0.55 of it.
QRgb shade_crossing(double cosine) {
  const double k = 0.55 + 0.45 * std::min(1.0, std::abs(cosine));
  return qRgb(static_cast<int>(std::lround(kCrossingColor.red() * k)), 0,
              static_cast<int>(std::lround(kCrossingColor.blue() * k)));
}

//! The median on-screen length of some edges (0 for none): how dense the defects are drawn.
template <class Edges, class PairOf>
double median_length(const std::vector<CanvasPoint>& canvas, const Edges& edges, PairOf pair_of) {
  std::vector<double> lengths;
  const std::size_t step = std::max<std::size_t>(1, edges.size() / 4096);  // a sample suffices
  for (std::size_t i = 0; i < edges.size(); i += step) {
    const VertexPair p = pair_of(edges[i]);
    lengths.push_back(std::hypot(canvas[p.v0].x - canvas[p.v1].x, canvas[p.v0].y - canvas[p.v1].y));
  }
  if (lengths.empty())
    return 0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

//! True if `font` puts ink on an image: offscreen, without a font file, text draws nothing.
bool text_renders(const QFont& font) {
  QImage probe(64, 64, QImage::Format_ARGB32);
  probe.fill(kBackground);
  {
    QPainter painter(&probe);
    painter.setFont(font);
    painter.setPen(kLegendColor);
    painter.drawText(QRectF(0, 0, 64, 64), Qt::AlignCenter, QStringLiteral("0A"));
  }
  for (int y = 0; y < probe.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(probe.constScanLine(y));
    for (int x = 0; x < probe.width(); ++x) {
      if (row[x] != kBackground.rgb())
        return true;
    }
  }
  return false;
}

bool near(QRgb pixel, const QColor& color, int tolerance) {
  return std::abs(qRed(pixel) - color.red()) <= tolerance &&
         std::abs(qGreen(pixel) - color.green()) <= tolerance &&
         std::abs(qBlue(pixel) - color.blue()) <= tolerance;
}

void check_vertex(const Soup& soup, Index v) {
  if (v >= soup.num_vertices()) {
    throw std::invalid_argument("draw_defect_snapshot: the report names vertex " +
                                std::to_string(v) + " but the soup has " +
                                std::to_string(soup.num_vertices()) + " vertices");
  }
}

//! Light grey of every face when counting (the shade does not matter there).
const QRgb kFlat = qRgb(165, 165, 165);

//! True if `polygon` passes through one vertex twice.
bool repeats_a_vertex(PolygonView polygon) {
  if (polygon.size() > 16) {
    std::vector<Index> sorted(polygon.begin(), polygon.end());
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
  }
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    for (std::size_t j = i + 1; j < polygon.size(); ++j) {
      if (polygon[i] == polygon[j])
        return true;
    }
  }
  return false;
}

//! The polygons of a soup that pass through one vertex twice, in face order, with their
//! triangles as the STL writer and repair cut them (triangles_as_written()): a keyhole polygon
//! (an outline and holes joined by slits) as one polygon with holes, the holes left open, where a
//! fan from its first corner would cover them; another as its simple loops.
struct PinchedPolygons {
  std::vector<Index> faces;
  PolygonTriangles triangles;  //!< of faces[i]: corners[first[i]] .. corners[first[i + 1] - 1]
};

PinchedPolygons pinched_polygons(const Soup& soup) {
  PinchedPolygons pinched;
  Soup polygons;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    if (polygon.size() > 3 && repeats_a_vertex(polygon)) {
      pinched.faces.push_back(static_cast<Index>(f));
      polygons.add_polygon(polygon);
    }
  }
  if (!pinched.faces.empty()) {
    polygons.positions = soup.positions;
    pinched.triangles = triangles_as_written(polygons);
  }
  return pinched;
}

//! Projects the vertices of `soup` in `frame` into `canvas_points` (resized) and fills its
//! surface into `canvas`, shaded, or all kFlat when `counting`; faces marked in `crossing` (empty,
//! or one flag per face) shaded violet.
void draw_surface(const Soup& soup, const Frame& frame, bool counting,
                  const std::vector<char>& crossing, std::vector<CanvasPoint>& canvas_points,
                  ZBufferCanvas& canvas) {
  canvas_points.resize(soup.num_vertices());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    canvas_points[v] = frame.to_canvas(soup.positions[v]);
  // The light comes from the upper left, in front: fixed to the camera, so every view is lit.
  Point light = frame.axes.right * -0.4 + frame.axes.up * 0.6 + frame.forward * 0.7;
  light.normalize();
  const PinchedPolygons pinched = pinched_polygons(soup);
  std::size_t next_pinched = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    QRgb color = kFlat;
    if (!counting) {
      Point normal(0, 0, 0);  // Newell's normal: fine for any simple polygon
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point p = frame.normalized(soup.positions[polygon[i]]);
        const Point q = frame.normalized(soup.positions[polygon[(i + 1) % polygon.size()]]);
        normal += Point((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                        (p[0] - q[0]) * (p[1] + q[1]));
      }
      const double length = normal.norm();
      const double cosine = length > 0 ? (normal | light) / length : 0;
      color = crossing.empty() || !crossing[f] ? shade(cosine) : shade_crossing(cosine);
    }
    if (next_pinched < pinched.faces.size() && pinched.faces[next_pinched] == f) {
      const PolygonTriangles& t = pinched.triangles;
      for (Index i = t.first[next_pinched]; i < t.first[next_pinched + 1]; ++i) {
        canvas.fill_triangle(canvas_points[polygon[t.corners[i][0]]],
                             canvas_points[polygon[t.corners[i][1]]],
                             canvas_points[polygon[t.corners[i][2]]], color);
      }
      ++next_pinched;
      continue;
    }
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      canvas.fill_triangle(canvas_points[polygon[0]], canvas_points[polygon[i]],
                           canvas_points[polygon[i + 1]], color);
    }
  }
}

//! Draws the defects of `report` on `canvas` (a `size` x `size` surface drawn by draw_surface,
//! vertices at `canvas_points`, `scale` pixels per unit) and counts the defect pixels; the result
//! takes the canvas's image. `counting` draws for choose_view (detail::count_defect_pixels), a
//! sample of the defects when they are many.
DefectSnapshot draw_defects(const DefectReport& report,
                            const std::vector<CanvasPoint>& canvas_points, double scale, int size,
                            bool counting, ZBufferCanvas& canvas) {
  const double pen_scale = std::max(1.0, size / 800.0);
  // Depth tolerance: three pixels' worth, so edges on the surface are not lost to rounding.
  const double tolerance = 3 / std::max(scale, 1e-300);
  const auto same = [](const VertexPair& pair) { return pair; };
  const auto vertices_of = [](const SingularEdge& edge) { return edge.vertices; };
  // Many defect edges (kFewestDense or more) shorter than kDenseLength pixels on screen (median)
  // are too dense to draw one by one: they tint the surface instead (not counted as defect
  // pixels), their hidden parts and vertex dots are left out, so the shape stays visible. Fewer
  // are drawn at full width with their dots however short they look (an edge seen end on).
  constexpr double kDenseLength = 6;
  constexpr std::size_t kFewestDense = 100;
  constexpr std::size_t kMostHiddenDrawn = 20000;
  // Counting, at most about kMostCounted edges and dots of each colour are drawn (every n-th; a
  // sample is enough to rank the views, and drawing 500,000 edges 14 times is not), and their
  // pixels count n times.
  constexpr std::size_t kMostCounted = 20000;
  const auto stride_for = [&](std::size_t n) {
    return counting ? std::max<std::size_t>(1, (n + kMostCounted - 1) / kMostCounted)
                    : std::size_t{1};
  };
  const std::size_t green_stride = stride_for(report.boundary_edges.size());
  const std::size_t red_stride =
      stride_for(std::max(report.singular_edges.size(),
                          report.singular_edge_vertices.size() + report.pinch_vertices.size()));
  const auto draw_edges = [&](const auto& edges, const auto& pair_of, double width, QRgb color,
                              QRgb hidden, std::size_t stride) {
    const double median = median_length(canvas_points, edges, pair_of);
    const bool few = edges.size() < kFewestDense;
    const bool dense = !few && median < kDenseLength && !counting;
    // Thinner where many edges are short on screen: a grid of defects stays a grid.
    const double shown =
        few ? width * pen_scale : std::max(1.0, std::min(width * pen_scale, median / 4));
    if (dense || edges.size() > kMostHiddenDrawn || counting)
      hidden = qRgba(0, 0, 0, 0);
    for (std::size_t i = 0; i < edges.size(); i += stride) {
      const VertexPair pair = pair_of(edges[i]);
      canvas.draw_line(canvas_points[pair.v0], canvas_points[pair.v1], shown, color, hidden,
                       tolerance, dense ? 0.45 : 1.0);
    }
    return dense ? 0.0 : shown;
  };
  draw_edges(report.boundary_edges, same, 2, kBoundaryColor.rgb(), qRgb(170, 225, 170),
             green_stride);
  const double red_width = draw_edges(report.singular_edges, vertices_of, 3, kSingularColor.rgb(),
                                      qRgb(245, 170, 170), red_stride);
  if (red_width > 0 || report.singular_edges.empty()) {
    const double radius = std::max(red_width / 2 + 0.5, std::min(3.5 * pen_scale, red_width * 1.2));
    for (std::size_t i = 0; i < report.singular_edge_vertices.size(); i += red_stride)
      canvas.draw_dot(canvas_points[report.singular_edge_vertices[i]], radius, kSingularColor.rgb(),
                      tolerance);
  }
  // No edge shows pinch vertices: always full size.
  for (std::size_t i = 0; i < report.pinch_vertices.size(); i += red_stride)
    canvas.draw_dot(canvas_points[report.pinch_vertices[i]], 3.5 * pen_scale, kSingularColor.rgb(),
                    tolerance);
  DefectSnapshot result;
  result.image = std::move(canvas.image());
  for (int y = 0; y < result.image.height(); ++y) {
    const QRgb* row = reinterpret_cast<const QRgb*>(result.image.constScanLine(y));
    for (int x = 0; x < result.image.width(); ++x) {
      result.red_pixels += near(row[x], kSingularColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
      result.green_pixels += near(row[x], kBoundaryColor, DefectSnapshot::kColorTolerance) ? 1 : 0;
      result.violet_pixels += is_violet(qRed(row[x]), qGreen(row[x]), qBlue(row[x])) ? 1 : 0;
    }
  }
  result.red_pixels *= red_stride;
  result.green_pixels *= green_stride;
  return result;
}

}  // namespace

bool is_violet(unsigned red, unsigned green, unsigned blue) {
  return blue >= 100 && green <= 50 && 10 * red >= 3 * blue && 10 * red <= 8 * blue &&
         red >= green + 40;
}

DefectSnapshot draw_defect_snapshot(const Soup& soup, const DefectReport& report,
                                    const SnapshotOptions& options, const Soup* frame_soup,
                                    const DefectReport* frame_report,
                                    const SelfIntersectionReport* crossings) {
  if (frame_soup != nullptr && frame_report == nullptr)
    throw std::invalid_argument("draw_defect_snapshot: frame_soup without frame_report");
  if (options.size < SnapshotOptions::kMinSize || options.size > SnapshotOptions::kMaxSize) {
    throw std::invalid_argument(
        "snapshot size must be " + std::to_string(SnapshotOptions::kMinSize) + " to " +
        std::to_string(SnapshotOptions::kMaxSize) + ", got " + std::to_string(options.size));
  }
  if (!(options.margin >= 0 && options.margin <= 0.45))
    throw std::invalid_argument("snapshot margin must be 0 to 0.45");
  if (!options.view.is_valid())
    throw std::invalid_argument("snapshot view: not a corner, an axis or automatic");
  validate_soup(soup);
  for (const SingularEdge& edge : report.singular_edges) {
    check_vertex(soup, edge.vertices.v0);
    check_vertex(soup, edge.vertices.v1);
  }
  for (const VertexPair& edge : report.boundary_edges) {
    check_vertex(soup, edge.v0);
    check_vertex(soup, edge.v1);
  }
  for (Index v : report.singular_edge_vertices)
    check_vertex(soup, v);
  for (Index v : report.pinch_vertices)
    check_vertex(soup, v);
  std::vector<char> crossing(crossings ? soup.num_faces() : 0, 0);
  if (crossings != nullptr) {
    for (Index f : crossings->faces) {
      if (f >= soup.num_faces()) {
        throw std::invalid_argument("draw_defect_snapshot: the self-intersections name face " +
                                    std::to_string(f) + " but the soup has " +
                                    std::to_string(soup.num_faces()) + " faces");
      }
      crossing[f] = 1;
    }
  }

  const double size = options.size;
  const double border = size * options.margin;

  // The legend: one line at the top, shrunk until it fits the width.
  const QString counts = QString::fromStdString(
      counted(report.singular_edges.size(), "singular edge") + ", " +
      counted(report.num_singular_vertices(), "singular vertex") + ", " +
      counted(report.boundary_edges.size(), "boundary edge") +
      (crossings ? ", " + counted(crossings->faces.size(), "self-intersecting face") : ""));
  const QString legend = options.title.empty()
                             ? counts
                             : QString::fromLocal8Bit(options.title.c_str()) + ": " + counts;
  QFont font;
  bool legend_drawn = false;
  double legend_height = 0;
  if (options.legend && QGuiApplication::instance() != nullptr) {
    double pixel_size = std::max(10.0, size / 40);
    font.setPixelSize(static_cast<int>(pixel_size));
    while (pixel_size > 6 && QFontMetricsF(font).horizontalAdvance(legend) > size - 2 * border) {
      pixel_size -= 1;
      font.setPixelSize(static_cast<int>(pixel_size));
    }
    if (text_renders(font)) {
      legend_drawn = true;
      legend_height = QFontMetricsF(font).height() + border / 2;
    }
  }
  const QRectF area(border, border + legend_height, size - 2 * border,
                    size - 2 * border - legend_height);
  const Placement placement =
      frame_soup ? place_model(*frame_soup, *frame_report) : place_model(soup, report);
  std::vector<CanvasPoint> canvas_points;
  const auto draw_along = [&](const SnapshotView& view) {
    SnapshotOptions along = options;
    along.view = view;
    const Frame frame = make_frame(frame_soup ? *frame_soup : soup, placement, along, area);
    ZBufferCanvas canvas(options.size, options.size, kBackground);
    draw_surface(soup, frame, false, crossing, canvas_points, canvas);
    DefectSnapshot result =
        draw_defects(report, canvas_points, frame.scale, options.size, false, canvas);
    result.view = view;
    return result;
  };
  DefectSnapshot result;
  if (!options.view.automatic) {
    result = draw_along(options.view);
  } else if (frame_soup != nullptr) {
    result = draw_along(choose_view(*frame_soup, *frame_report, options).view);
  } else {
    // The small pictures rank the views; drawn full size, the winner must still beat iso (line
    // widths and the tint of dense defects depend on the size), else iso it is.
    const SnapshotView best = choose_view(soup, report, options).view;
    result = draw_along(SnapshotView::iso());
    if (best != SnapshotView::iso()) {
      DefectSnapshot other = draw_along(best);
      if (other.red_pixels + other.green_pixels > result.red_pixels + result.green_pixels)
        result = std::move(other);
    }
  }
  result.legend_drawn = legend_drawn;
  if (result.legend_drawn) {
    QPainter painter(&result.image);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    painter.setFont(font);
    painter.setPen(kLegendColor);
    painter.drawText(QRectF(border, border / 2, size - 2 * border, legend_height),
                     Qt::AlignLeft | Qt::AlignTop, legend);
  }
  return result;
}

std::vector<std::size_t> detail::count_defect_pixels(const Soup& soup, const DefectReport& report,
                                                     const SnapshotOptions& options,
                                                     const std::vector<SnapshotView>& views) {
  const double border = options.size * options.margin;
  const QRectF area(border, border, options.size - 2 * border, options.size - 2 * border);
  const Placement placement = place_model(soup, report);
  // A view and its opposite (x and -x, iso and -x-y-z) are mirror images with depths reversed:
  // one pass over the faces fills both (ZBufferCanvas::opposite). The jobs (a view, with its
  // opposite when that is asked for too) are independent: up to kMostThreads threads draw them,
  // each with its own canvas and projected points, each count in its own slot, so the result
  // does not depend on the threads.
  std::vector<std::size_t> pair_of(views.size(), views.size()), jobs;
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (pair_of[i] != views.size() && pair_of[i] < i)
      continue;  // drawn with its opposite
    jobs.push_back(i);
    const SnapshotView back{false, -views[i].x, -views[i].y, -views[i].z};
    for (std::size_t j = i + 1; j < views.size(); ++j) {
      if (views[j] == back && pair_of[j] == views.size()) {
        pair_of[i] = j, pair_of[j] = i;
        break;
      }
    }
  }
  constexpr unsigned kMostThreads = 4;
  const std::size_t threads = std::max<std::size_t>(
      1, std::min<std::size_t>({jobs.size(), kMostThreads, std::thread::hardware_concurrency()}));
  std::vector<std::size_t> counts(views.size(), 0);
  std::vector<std::exception_ptr> failures(threads);
  const auto work = [&](std::size_t first) {
    try {
      std::vector<CanvasPoint> points;
      SnapshotOptions along = options;
      for (std::size_t k = first; k < jobs.size(); k += threads) {
        const std::size_t i = jobs[k], j = pair_of[i];
        along.view = views[i];
        const Frame frame = make_frame(soup, placement, along, area);
        ZBufferCanvas canvas(options.size, options.size, kBackground);
        if (j != views.size())
          canvas.keep_farthest();
        draw_surface(soup, frame, true, {}, points, canvas);
        std::optional<ZBufferCanvas> back;
        if (j != views.size())
          back.emplace(canvas.opposite(kFlat));
        const DefectSnapshot drawn =
            draw_defects(report, points, frame.scale, options.size, true, canvas);
        counts[i] = drawn.red_pixels + drawn.green_pixels;
        if (j != views.size()) {
          for (CanvasPoint& point : points)
            point.x = options.size - point.x, point.depth = -point.depth;
          const DefectSnapshot mirrored =
              draw_defects(report, points, frame.scale, options.size, true, *back);
          counts[j] = mirrored.red_pixels + mirrored.green_pixels;
        }
      }
    } catch (...) {
      failures[first] = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < threads; ++t)
    helpers.emplace_back(work, t);
  work(0);
  for (std::thread& helper : helpers)
    helper.join();
  for (const std::exception_ptr& failure : failures) {
    if (failure)
      std::rethrow_exception(failure);
  }
  return counts;
}

DefectSnapshot side_by_side(const DefectSnapshot& left, const DefectSnapshot& right) {
  constexpr int kRule = 2;
  DefectSnapshot both;
  both.image = QImage(left.image.width() + kRule + right.image.width(),
                      std::max(left.image.height(), right.image.height()), QImage::Format_ARGB32);
  if (both.image.isNull())
    throw std::bad_alloc();
  both.image.fill(kBackground);
  QPainter painter(&both.image);
  painter.drawImage(0, 0, left.image);
  painter.fillRect(left.image.width(), 0, kRule, both.image.height(), kEdgeColor);
  painter.drawImage(left.image.width() + kRule, 0, right.image);
  painter.end();
  both.legend_drawn = left.legend_drawn && right.legend_drawn;
  both.view = left.view;
  both.red_pixels = left.red_pixels + right.red_pixels;
  both.green_pixels = left.green_pixels + right.green_pixels;
  both.violet_pixels = left.violet_pixels + right.violet_pixels;
  return both;
}

}  // namespace meshbridge::cli
