// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A 3MF package (a zip archive, 3MF Core Specification 1.2, chapter 2) held in memory, through
// libzip: its root model part found through the package relationships, read whole (inflated by
// libdeflate) or as stored (for inflate_chunks.h), and a copy of the package with that part
// replaced, for lib3mf to read the rest.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

struct zip;         // libzip's archive
struct zip_source;  // libzip's source

namespace meshbridge::detail {

//! The bytes of a part, followed by one NUL (not counted in `size`).
struct PartBytes {
  std::unique_ptr<char[]> data;  // not initialised before it is filled: no pass to clear it
  std::size_t size = 0;
  std::string_view view() const { return {data.get(), size}; }
};

//! Where a part is in the package and what its header says.
struct PartStat {
  std::uint64_t index = 0;
  std::uint64_t size = 0;             //!< inflated
  std::uint64_t compressed_size = 0;  //!< as stored
  std::uint32_t crc = 0;              //!< CRC-32 of the inflated bytes
  bool deflated = false;              //!< else stored
};

class Package3mf {
 public:
  //! Opens the package in `data` (`size` bytes, which must outlive this). Check is_open().
  Package3mf(const void* data, std::size_t size);
  ~Package3mf();
  Package3mf(const Package3mf&) = delete;
  Package3mf& operator=(const Package3mf&) = delete;

  bool is_open() const { return archive_ != nullptr; }
  //! The name of the root model part ("3D/3dmodel.model"), from the target of the package
  //! relationship of type .../3dmodel in _rels/.rels; empty if there is none, or if the package
  //! holds another model part (the production extension's parts, which lib3mf reads alone).
  std::string root_model() const;
  //! The whole part `name` into `bytes`; false if it cannot be read (or its CRC-32 does not
  //! match).
  bool read(const std::string& name, PartBytes& bytes) const;
  //! The stored (deflated) bytes of part `name` into `compressed`, what its header says into
  //! `part`; false if it cannot be read, is not deflated, or claims more than deflate can give.
  bool read_deflated(const std::string& name, PartStat& part, PartBytes& compressed) const;
  //! As read_deflated(), without a copy: where the deflated bytes of part `name`
  //! (`part.compressed_size` of them) are in the package's own memory; nullptr where the zip
  //! records do not say it plainly (zip64, encryption, a central directory that does not agree
  //! with libzip's): read_deflated() then copies them out through libzip.
  const unsigned char* deflated_in_place(const std::string& name, PartStat& part) const;
  //! The whole package with part `name` replaced by `content` (stored, not compressed), every
  //! other part as it was; empty on failure. Closes the package (is_open() is false after it).
  std::vector<unsigned char> replaced(const std::string& name, const std::string& content);

 private:
  bool stat(const std::string& name, PartStat& part) const;
  // The part's bytes as stored (`compressed`) or inflated by libzip into `out`.
  bool read_raw(const PartStat& part, bool compressed, char* out) const;

  const unsigned char* data_;
  std::size_t size_;
  ::zip* archive_ = nullptr;
  ::zip_source* source_ = nullptr;
};

}  // namespace meshbridge::detail
