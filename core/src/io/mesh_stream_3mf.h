// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The meshes of a 3MF model part read while the part is inflated (inflate_chunks.h): the
// vertex and triangle lists scanned chunk by chunk (mesh_scan_3mf.h) as they come out of the
// inflater, the rest of the part (small) kept as the structure that read_structure()
// (mesh_xml_3mf.h) walks afterwards. Never more than a chunk of the text in memory, and no pass
// over the whole text but the inflater's and the scan's. Only for text the scan reads whole:
// where it gives up (or a list belongs to no mesh read here) this route says so, and the part
// is read whole (read_meshes_xml()), which gives the same meshes.

#include "io/mesh_xml_3mf.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace meshbridge::detail {

//! The model part deflated in `compressed` (`size` bytes; `inflated_size` bytes and CRC-32
//! `crc` inflated) read as read_meshes_xml() reads it, into `meshes` and `stripped`; false
//! (`meshes` empty) when this route cannot tell: the part is not of the narrow form the scan
//! reads, the deflate stream is broken, or MeshBridge was built without ISA-L.
bool read_meshes_streamed(const unsigned char* compressed, std::size_t size,
                          std::uint64_t inflated_size, std::uint32_t crc,
                          std::map<std::uint32_t, MeshXml>& meshes, std::string& stripped);

}  // namespace meshbridge::detail
