// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers to text through std::to_chars into a block buffer, flushed to an AtomicOutput.

#include "io/atomic_write.h"

#include <charconv>
#include <cstdint>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

//! Buffers text and hands it to `out` in 1 MiB blocks. Doubles are written in their shortest
//! form that reads back to the same double (std::to_chars), so text formats round-trip exactly.
class TextOutput {
 public:
  explicit TextOutput(AtomicOutput& out) : out_(out) { buffer_.reserve(kBlock + 512); }
  ~TextOutput() = default;  // call flush(): a destructor must not throw
  TextOutput(const TextOutput&) = delete;
  TextOutput& operator=(const TextOutput&) = delete;

  TextOutput& text(std::string_view s) {
    buffer_.insert(buffer_.end(), s.begin(), s.end());
    return maybe_flush();
  }
  TextOutput& ch(char c) {
    buffer_.push_back(c);
    return maybe_flush();
  }
  TextOutput& number(double value) { return put(value); }
  TextOutput& number(std::uint64_t value) { return put(value); }
  TextOutput& number(std::int64_t value) { return put(value); }
  TextOutput& number(unsigned value) { return put(static_cast<std::uint64_t>(value)); }
  void flush() {
    out_.write(buffer_.data(), buffer_.size());
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kBlock = 1 << 20;
  template <class T>
  TextOutput& put(T value) {
    char digits[64];
    const auto result = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.insert(buffer_.end(), digits, result.ptr);
    return maybe_flush();
  }
  TextOutput& maybe_flush() {
    if (buffer_.size() >= kBlock)
      flush();
    return *this;
  }
  AtomicOutput& out_;
  std::vector<char> buffer_;
};

}  // namespace meshbridge::detail
