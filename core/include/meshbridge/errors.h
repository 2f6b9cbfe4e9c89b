// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file errors.h
//! Typed exceptions. Every message names the offending element or file.

#include <stdexcept>
#include <string>

namespace meshbridge {

//! A soup that violates a precondition: index out of range, arity < 3, non-finite coordinate.
class InvalidSoupError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

//! A file that cannot be read: missing, unreadable, empty, unknown format or malformed.
class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A file that cannot be written. The previous content at that path is left untouched.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace meshbridge
