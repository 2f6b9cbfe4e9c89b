// SPDX-License-Identifier: GPL-3.0-or-later
// ReadInfo as one line of text for reports and warnings.

#include "meshbridge/io.h"

#include "meshbridge/counted.h"

#include <string>

namespace meshbridge {

std::string describe_reading(const ReadInfo& info) {
  std::string text = counted(info.declared_faces, "face record") + ": ";
  if (info.faces_split + info.faces_set_aside == 0) {
    text += "all kept";
  } else {
    text += std::to_string(info.faces_kept) + " kept";
    const std::size_t pinched = info.faces_split - info.keyhole_polygons;
    if (pinched > 0)
      text += ", " + std::to_string(pinched) + " split (pinched: a vertex revisited)";
    if (info.keyhole_polygons > 0) {
      text += ", " + counted(info.keyhole_polygons, "keyhole polygon") +
              " (an outline and holes joined by slits: cut into triangles, the holes left open)";
    }
    if (info.faces_set_aside > 0) {
      text += ", " + std::to_string(info.faces_set_aside) + " set aside (< 3 distinct corners";
      if (info.faces_without_corners > 0)
        text += "; " + std::to_string(info.faces_without_corners) + " without any corner";
      text += ")";
    }
  }
  if (info.vertices_welded_by_position > 0) {
    text += "; the file repeats each vertex per face: " +
            counted(info.vertices_welded_by_position, "copy") + " welded by exact position";
  }
  if (info.strip_joins > 0) {
    text +=
        " (" + counted(info.strip_joins, "degenerate strip triangle") + " linking runs skipped)";
  }
  if (info.dangling_edges + info.lone_points > 0) {
    text += "; ";
    if (info.dangling_edges > 0)
      text += counted(info.dangling_edges, "dangling edge");
    if (info.dangling_edges > 0 && info.lone_points > 0)
      text += ", ";
    if (info.lone_points > 0)
      text += counted(info.lone_points, "lone point");
    text += " (not part of the surface, not written back)";
  }
  if (info.empty_records > 0) {
    text += "; " + counted(info.empty_records, "record") +
            " holding no face skipped (an OBJ l or p without an index, a PLY strip run of fewer "
            "than 3 vertices)";
  }
  if (info.trailing_bytes > 0) {
    text += "; " + counted(info.trailing_bytes, "byte") +
            " after the end of the mesh not read (padding, or items a false count leaves out)";
  }
  if (info.unknown_records > 0)
    text += "; " + counted(info.unknown_records, "line") + " with an unknown keyword skipped";
  if (info.color_map_indices > 0) {
    text += "; " + std::to_string(info.color_map_indices) +
            (info.color_map_indices == 1 ? " colour given as a colour-map index"
                                         : " colours given as colour-map indices") +
            " not kept (Geomview's colour map is not read)";
  }
  return text;
}

}  // namespace meshbridge
