// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// TEMPORARY bridge: the previous OpenMesh-based reader and writer, behind the new layout, for the
// formats whose own reader/writer is not written yet. Delete it with its last caller.

#include "io/atomic_write.h"
#include "io/mapped_file.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/io.h"

#include <string>

namespace meshbridge::detail {

//! Reads `file` with OpenMesh's reader for `ext` ("obj", "off", "ply", "stl") through the old
//! pre-checks; fills declared counts and faces_dropped_by_reader. \throw ReadError
void read_with_openmesh(const MappedFile& file, const std::string& ext, Soup& soup, ReadInfo& info);
//! Writes `mesh` with OpenMesh's writer for `ext` to `out.temporary_path()`. \throw WriteError
void write_with_openmesh(AtomicOutput& out, const std::string& ext, const IndexedMesh& mesh);

}  // namespace meshbridge::detail
