// SPDX-License-Identifier: GPL-3.0-or-later
// OFF writer. For now OpenMesh's writer (openmesh_legacy.h).

#include "io/formats.h"
#include "io/openmesh_legacy.h"

namespace meshbridge::detail {

void write_off(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes*,
               const WriteOptions&) {
  write_with_openmesh(out, "off", mesh);
}

}  // namespace meshbridge::detail
