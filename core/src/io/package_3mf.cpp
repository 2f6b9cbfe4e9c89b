// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/package_3mf.h"

#include <libdeflate.h>
#include <zip.h>
#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace meshbridge::detail {

Package3mf::Package3mf(const void* data, std::size_t size)
    : data_(static_cast<const unsigned char*>(data)), size_(size) {
  zip_error_t error;
  zip_error_init(&error);
  source_ = zip_source_buffer_create(data, size, 0, &error);
  if (source_ != nullptr) {
    archive_ = zip_open_from_source(source_, 0, &error);
    if (archive_ == nullptr) {
      zip_source_free(source_);
      source_ = nullptr;
    }
  }
  zip_error_fini(&error);
}

Package3mf::~Package3mf() {
  if (archive_ != nullptr)
    zip_discard(archive_);  // frees the source too
  else if (source_ != nullptr)
    zip_source_free(source_);
}

std::string Package3mf::root_model() const {
  PartBytes rels;
  if (!read("_rels/.rels", rels))
    return {};
  pugi::xml_document document;
  if (!document.load_buffer_inplace(rels.data.get(), rels.size))
    return {};
  std::string root;
  for (pugi::xml_node r : document.child("Relationships").children("Relationship")) {
    const std::string type = r.attribute("Type").value();
    const std::string suffix = "/3dmodel";
    if (type.size() > suffix.size() &&
        type.compare(type.size() - suffix.size(), suffix.size(), suffix) == 0) {
      if (!root.empty())
        return {};  // two roots: lib3mf's own choice
      root = r.attribute("Target").value();
    }
  }
  if (!root.empty() && root[0] == '/')
    root.erase(0, 1);
  // Every part named *.model other than the root: models of the production extension.
  const zip_int64_t entries = zip_get_num_entries(archive_, 0);
  for (zip_int64_t i = 0; i < entries; ++i) {
    const char* name = zip_get_name(archive_, static_cast<zip_uint64_t>(i), 0);
    if (name == nullptr)
      return {};
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower.size() >= 6 && lower.compare(lower.size() - 6, 6, ".model") == 0 && name != root)
      return {};
  }
  return root;
}

bool Package3mf::stat(const std::string& name, PartStat& part) const {
  const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
  zip_stat_t stat;
  if (index < 0 || zip_stat_index(archive_, static_cast<zip_uint64_t>(index), 0, &stat) != 0 ||
      (stat.valid & ZIP_STAT_SIZE) == 0 || (stat.valid & ZIP_STAT_COMP_SIZE) == 0 ||
      (stat.valid & ZIP_STAT_COMP_METHOD) == 0 || (stat.valid & ZIP_STAT_CRC) == 0 ||
      stat.size > (std::uint64_t(1) << 40) || stat.comp_size > size_) {
    return false;  // (a part's stored bytes cannot be more than the whole package's)
  }
  // Deflate expands at most 1032 times: a larger size is a false header (a zip bomb's), left to
  // lib3mf rather than allocated.
  if (stat.comp_method == ZIP_CM_DEFLATE && stat.size > 1032 * stat.comp_size + 1024)
    return false;
  if (stat.comp_method != ZIP_CM_DEFLATE && stat.size > size_)
    return false;  // stored (or another method, left to libzip): never more than the package
  part.index = static_cast<std::uint64_t>(index);
  part.size = stat.size;
  part.compressed_size = stat.comp_size;
  part.crc = stat.crc;
  part.deflated = stat.comp_method == ZIP_CM_DEFLATE;
  return true;
}

bool Package3mf::read_raw(const PartStat& part, bool compressed, char* out) const {
  const std::size_t wanted =
      static_cast<std::size_t>(compressed ? part.compressed_size : part.size);
  zip_file_t* file = zip_fopen_index(archive_, part.index, compressed ? ZIP_FL_COMPRESSED : 0);
  if (file == nullptr)
    return false;
  const zip_int64_t got = wanted == 0 ? 0 : zip_fread(file, out, wanted);
  zip_fclose(file);
  return got >= 0 && static_cast<std::size_t>(got) == wanted;
}

bool Package3mf::read_deflated(const std::string& name, PartStat& part,
                               PartBytes& compressed) const {
  if (!stat(name, part) || !part.deflated)
    return false;
  compressed.size = static_cast<std::size_t>(part.compressed_size);
  compressed.data.reset(new char[compressed.size + 1]);
  compressed.data[compressed.size] = '\0';
  return read_raw(part, true, compressed.data.get());
}

bool Package3mf::read(const std::string& name, PartBytes& bytes) const {
  PartStat part;
  if (!stat(name, part))
    return false;
  bytes.size = static_cast<std::size_t>(part.size);
  bytes.data.reset(new char[bytes.size + 1]);
  bytes.data[bytes.size] = '\0';
  // Deflated parts are inflated whole by libdeflate (about twice zlib's speed), the rest by
  // libzip.
  if (!part.deflated)
    return read_raw(part, false, bytes.data.get());
  PartBytes compressed;
  compressed.size = static_cast<std::size_t>(part.compressed_size);
  compressed.data.reset(new char[compressed.size + 1]);
  if (!read_raw(part, true, compressed.data.get()))
    return false;
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  if (inflater == nullptr)
    return false;
  std::size_t size = 0;
  const libdeflate_result result = libdeflate_deflate_decompress(
      inflater, compressed.data.get(), compressed.size, bytes.data.get(), bytes.size, &size);
  libdeflate_free_decompressor(inflater);
  return result == LIBDEFLATE_SUCCESS && size == bytes.size &&
         libdeflate_crc32(0, bytes.data.get(), size) == part.crc;
}

namespace {

// Little-endian fields of the zip records (APPNOTE.TXT 4.3).
std::uint32_t u16(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8;
}
std::uint32_t u32(const unsigned char* p) {
  return u16(p) | u16(p + 2) << 16;
}
std::uint64_t u64(const unsigned char* p) {
  return u32(p) | std::uint64_t(u32(p + 4)) << 32;
}

// The central directory of the zip archive [data, data + size): where it begins and how many
// entries it has, from the end of central directory record (the last one whose comment ends
// the archive) or the zip64 record it points to; false where they are not plain.
bool central_directory(const unsigned char* data, std::size_t size, std::uint64_t& directory,
                       std::uint64_t& entries) {
  const unsigned char* end = data + size;
  const unsigned char* record = nullptr;
  for (std::size_t back = 22; back <= size && back <= 22 + 0xffff && record == nullptr; ++back) {
    if (u32(end - back) == 0x06054b50 && 22 + u16(end - back + 20) == back)
      record = end - back;
  }
  if (record == nullptr || u16(record + 4) != 0)
    return false;  // none, or several disks
  entries = u16(record + 10);
  directory = u32(record + 16);
  std::uint64_t length = u32(record + 12);
  if (entries == 0xffff || directory == 0xffffffff || length == 0xffffffff) {
    // zip64: the locator just before the record, and the zip64 record it points to.
    const std::size_t at = std::size_t(record - data);
    if (at < 20 || u32(record - 20) != 0x07064b50)
      return false;
    const std::uint64_t zip64 = u64(record - 20 + 8);
    if (zip64 > at - 20 || at - 20 - zip64 < 56 || u32(data + zip64) != 0x06064b50)
      return false;
    entries = u64(data + zip64 + 32);
    length = u64(data + zip64 + 40);
    directory = u64(data + zip64 + 48);
  }
  return directory <= size && length <= size - directory;
}

// The compressed size and local header offset of the central directory entry at `entry`
// (`length` bytes), from its zip64 extra field where they are 0xffffffff (lib3mf writes them
// there); false where that field lacks them.
bool wide_sizes(const unsigned char* entry, std::size_t length, std::uint64_t& compressed,
                std::uint64_t& local) {
  compressed = u32(entry + 20);
  local = u32(entry + 42);
  std::uint64_t inflated = u32(entry + 24);
  const unsigned char* extra = entry + 46 + u16(entry + 28);
  const unsigned char* extra_end = std::min(extra + u16(entry + 30), entry + length);
  while (extra_end - extra >= 4 && (compressed == 0xffffffff || local == 0xffffffff)) {
    const unsigned char* field = extra + 4;
    const unsigned char* past = field + u16(extra + 2);
    if (past > extra_end)
      return false;
    if (u16(extra) == 1) {  // in order: inflated size, compressed size, local header offset
      for (std::uint64_t* value : {&inflated, &compressed, &local}) {
        if (*value == 0xffffffff && past - field >= 8) {
          *value = u64(field);
          field += 8;
        }
      }
      break;
    }
    extra = past;
  }
  return compressed != 0xffffffff && local != 0xffffffff;
}

}  // namespace

const unsigned char* Package3mf::deflated_in_place(const std::string& name, PartStat& part) const {
  std::uint64_t directory = 0, entries = 0;
  if (!stat(name, part) || !part.deflated || !central_directory(data_, size_, directory, entries) ||
      part.index >= entries) {
    return nullptr;
  }
  // libzip numbers the entries in directory order: entry part.index, if its name agrees.
  const unsigned char* end = data_ + size_;
  const unsigned char* entry = data_ + directory;
  std::size_t length = 0;
  for (std::uint64_t i = 0;; ++i, entry += length) {
    if (end - entry < 46 || u32(entry) != 0x02014b50)
      return nullptr;
    length = 46 + u16(entry + 28) + u16(entry + 30) + u16(entry + 32);
    if (std::size_t(end - entry) < length)
      return nullptr;
    if (i == part.index)
      break;
  }
  std::uint64_t compressed = 0, local = 0;
  if (u16(entry + 28) != name.size() || std::memcmp(entry + 46, name.data(), name.size()) != 0 ||
      (u16(entry + 8) & 1) != 0 || u16(entry + 10) != 8 || u32(entry + 16) != part.crc ||
      !wide_sizes(entry, length, compressed, local) || compressed != part.compressed_size ||
      local >= size_ || size_ - local < 30) {
    return nullptr;  // encrypted, not deflated, or read otherwise by libzip
  }
  const unsigned char* header = data_ + local;
  if (u32(header) != 0x04034b50 || u16(header + 8) != 8)
    return nullptr;
  const std::uint64_t begin = local + 30 + u16(header + 26) + u16(header + 28);
  if (begin > size_ || size_ - begin < part.compressed_size)
    return nullptr;
  return data_ + begin;
}

std::vector<unsigned char> Package3mf::replaced(const std::string& name,
                                                const std::string& content) {
  std::vector<unsigned char> package;
  const zip_int64_t index = zip_name_locate(archive_, name.c_str(), 0);
  if (index < 0)
    return package;
  zip_source_t* part = zip_source_buffer(archive_, content.data(), content.size(), 0);
  if (part == nullptr)
    return package;
  if (zip_file_replace(archive_, static_cast<zip_uint64_t>(index), part, 0) != 0) {
    zip_source_free(part);
    return package;
  }
  if (zip_set_file_compression(archive_, static_cast<zip_uint64_t>(index), ZIP_CM_STORE, 0) != 0)
    return package;
  // The archive is written back into its source (a new buffer of the source's own: the mapped
  // file is not touched), the other parts copied as they are.
  zip_source_keep(source_);
  const bool written = zip_close(archive_) == 0;
  if (!written)
    zip_discard(archive_);
  archive_ = nullptr;
  zip_stat_t stat;
  if (written && zip_source_stat(source_, &stat) == 0 && (stat.valid & ZIP_STAT_SIZE) != 0 &&
      zip_source_open(source_) == 0) {
    package.resize(static_cast<std::size_t>(stat.size));
    const zip_int64_t got = zip_source_read(source_, package.data(), package.size());
    zip_source_close(source_);
    if (got < 0 || static_cast<std::size_t>(got) != package.size())
      package.clear();
  }
  zip_source_free(source_);
  source_ = nullptr;
  return package;
}

}  // namespace meshbridge::detail
