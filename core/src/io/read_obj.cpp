// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ reader. For now OpenMesh's reader behind the old pre-checks (openmesh_legacy.h).

#include "io/formats.h"
#include "io/openmesh_legacy.h"

namespace meshbridge::detail {

void read_obj(const MappedFile& file, Soup& soup, ReadInfo& info, MeshAttributes*) {
  read_with_openmesh(file, "obj", soup, info);
}

}  // namespace meshbridge::detail
