// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ writer. For now OpenMesh's writer (openmesh_legacy.h).

#include "io/formats.h"
#include "io/openmesh_legacy.h"

namespace meshbridge::detail {

void write_obj(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes*,
               const WriteOptions&) {
  write_with_openmesh(out, "obj", mesh);
}

}  // namespace meshbridge::detail
