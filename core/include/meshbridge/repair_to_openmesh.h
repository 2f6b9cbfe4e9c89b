// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file repair_to_openmesh.h
//! Repair straight into an OpenMesh mesh, at OpenMesh's own speed on clean input.

#include "meshbridge/mesh_types.h"
#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

namespace meshbridge {

//! The repaired mesh as OpenMesh holds it, with provenance properties `v:origin` and `f:origin`.
struct OpenMeshRepair {
  PolyMesh mesh;
  RepairReport report;
  bool fast_path = false;  //!< true if the input was already a repaired mesh (see below)
};

//! The same result as `to_openmesh(repair(soup, options).mesh)`, faster on clean input.
//!
//! When the options ask for no detection reports, no cleanup and no hole filling, the soup is
//! first handed to OpenMesh as it is: if every add_face succeeds, the mesh has no boundary, no two
//! components' bounding boxes meet and every component is oriented outward, that mesh *is* the
//! repair (nothing to weld, split, flip or cut; no shell can be another's cavity), and the work
//! is OpenMesh's own build plus linear checks. Otherwise (the first refused face ends the
//! attempt) the full repair runs: open parts (gap closing, open orientation), shells whose boxes
//! meet (nesting) and everything else. `fast_path` tells which way was taken.
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element
OpenMeshRepair repair_to_openmesh(const Soup& soup, const RepairOptions& options = {});

}  // namespace meshbridge
