// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/preview_repair.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/validate.h"

#include "detection.h"
#include "pipeline/orientation.h"
#include "working_soup.h"

#include <vector>

namespace meshbridge {

DefectReport detect_defects(const Soup& soup, OrientationPreview* orientation,
                            AmbiguousNesting nested) {
  if (orientation == nullptr)
    return detect_defects(soup);
  validate_soup(soup);
  const detail::WorkingSoup working(soup);
  std::vector<Index> mate;
  DefectReport report = detail::detect(working, &mate);
  *orientation = OrientationPreview();
  if (!report.watertight || !working.is_identity())
    return report;
  detail::SidePairing pairing;
  pairing.mate = std::move(mate);
  pairing.flipped.assign(soup.num_faces(), 0);
  const detail::GroupedSides grouped{detail::CornerFaces(soup), EdgeBridges()};
  orientation->computed = true;
  orientation->ambiguous_nested_shells = detail::orient_components(soup, grouped, pairing, nested);
  for (char f : pairing.flipped)
    orientation->faces_flipped += f;
  return report;
}

}  // namespace meshbridge
