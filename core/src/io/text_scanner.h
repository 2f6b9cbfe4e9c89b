// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A cursor over the text of a mapped file: blanks, words, numbers and line ends, counting lines.

#include "io/parse_numbers.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace meshbridge::detail {

//! Where the text of [first, last) starts: after a UTF-8 byte order mark, if the file has one
//! (some Windows editors and exporters write it before "OFF" or the first OBJ record).
inline const char* after_byte_order_mark(const char* first, const char* last) {
  return last - first >= 3 && static_cast<unsigned char>(first[0]) == 0xEF &&
                 static_cast<unsigned char>(first[1]) == 0xBB &&
                 static_cast<unsigned char>(first[2]) == 0xBF
             ? first + 3
             : first;
}

//! Walks [first, last) for the text readers (OBJ, OFF, ASCII PLY and STL).
//! Blanks are ' ', '\t', '\r', '\v', '\f' and, when enabled, an OBJ line continuation (a
//! backslash right before the line end). A '\n' is never a blank: readers see line ends.
//! With `hash_ends_line`, a '#' where a word would start ends the line's content (a comment).
class TextScanner {
 public:
  TextScanner(const char* first, const char* last, bool backslash_continues = false,
              bool hash_ends_line = false)
      : first_(first),
        p_(first),
        end_(last),
        continuations_(backslash_continues),
        hash_comments_(hash_ends_line) {}

  const char* position() const { return p_; }
  bool at_end() const { return p_ == end_; }
  std::size_t line() const { return line_; }  //!< 1-based number of the current line

  //! Skips blanks (and continuations) within the line.
  void skip_blanks() {
    while (p_ != end_) {
      const char c = *p_;
      if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
        ++p_;
      } else if (c == '\\' && continuations_ && continues_line(p_ + 1)) {
        ++p_;
        while (*p_ != '\n')
          ++p_;
        ++p_;
        ++line_;
      } else {
        return;
      }
    }
  }
  //! After the blanks: at the end of the line (or of the file)?
  bool at_line_end() {
    skip_blanks();
    return p_ == end_ || *p_ == '\n' || (hash_comments_ && *p_ == '#');
  }
  //! Moves past the next '\n' (or to the end of the file); continued lines are one line. With
  //! `hash_ends_line`, a comment ends at its line's end even when it ends in a backslash (a
  //! Windows path, say): a comment never continues onto the next record.
  void next_line() {
    bool in_comment = false;
    while (p_ != end_) {
      const char c = *p_++;
      if (c == '\n') {
        ++line_;
        return;
      }
      // '#' at the start of a word begins a comment ("g part#2" is a name).
      in_comment = in_comment || (c == '#' && hash_comments_ &&
                                  (p_ - 1 == first_ || is_blank_or_newline(p_[-2])));
      if (c == '\\' && continuations_ && !in_comment && continues_line(p_)) {
        while (*p_ != '\n')
          ++p_;
        ++p_;
        ++line_;
      }
    }
  }
  //! Moves past the next '\n' (or to the end of the file), continuation or not: the rest of a
  //! comment line.
  void skip_physical_line() {
    while (p_ != end_) {
      if (*p_++ == '\n') {
        ++line_;
        return;
      }
    }
  }
  //! The run of non-blank characters at the cursor (empty at a line end), consumed.
  std::string_view word() {
    skip_blanks();
    const char* start = p_;
    while (p_ != end_ && !is_blank_or_newline(*p_) &&
           !(*p_ == '\\' && continuations_ && continues_line(p_ + 1)))
      ++p_;
    return {start, static_cast<std::size_t>(p_ - start)};
  }
  //! The next word parsed as a number; false (cursor after the blanks) if it is not one whole.
  bool number(double& value) {
    skip_blanks();
    const char* e = parse_double(p_, end_, value);
    if (e == nullptr || (e != end_ && !is_blank_or_newline(*e) && !continues_at(e)))
      return false;
    p_ = e;
    return true;
  }
  bool integer(std::int64_t& value) {
    skip_blanks();
    const char* e = parse_integer(p_, end_, value);
    if (e == nullptr || (e != end_ && !is_blank_or_newline(*e) && !continues_at(e)))
      return false;
    p_ = e;
    return true;
  }
  //! Skips blanks, line ends and '#' comments (to the end of their line), as OFF allows.
  void skip_space_and_comments() {
    for (;;) {
      skip_blanks();
      if (p_ == end_)
        return;
      if (*p_ == '\n') {
        ++p_;
        ++line_;
      } else if (*p_ == '#') {
        while (p_ != end_ && *p_ != '\n')
          ++p_;
      } else {
        return;
      }
    }
  }
  //! Advances the cursor by `n` characters of the current line (caller checked they exist).
  void advance(std::size_t n) { p_ += n; }
  //! Moves the cursor back to `p`, on the current line and not before the start (e.g. into a
  //! word just read).
  void back_to(const char* p) {
    if (p >= first_ && p <= p_ && std::find(p, p_, '\n') == p_)
      p_ = p;
  }

  static bool is_blank_or_newline(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  }

 private:
  // A backslash at `after - 1` continues the line if only '\r' stands between it and '\n'.
  bool continues_line(const char* after) const {
    while (after != end_ && *after == '\r')
      ++after;
    return after != end_ && *after == '\n';
  }
  bool continues_at(const char* at) const {
    return continuations_ && *at == '\\' && continues_line(at + 1);
  }

  const char* first_;
  const char* p_;
  const char* end_;
  bool continuations_;
  bool hash_comments_;
  std::size_t line_ = 1;
};

}  // namespace meshbridge::detail
