// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A minimal JSON object writer for reports (numbers, booleans, strings, index lists).

#include "meshbridge/defect_report.h"

#include <sstream>
#include <string>
#include <vector>

namespace meshbridge::detail {

class JsonObject {
 public:
  template <class T>
  JsonObject& number(const char* key, T value) {
    next(key);
    out_ << value;
    return *this;
  }
  JsonObject& boolean(const char* key, bool value) {
    next(key);
    out_ << (value ? "true" : "false");
    return *this;
  }
  JsonObject& string(const char* key, const std::string& value);
  JsonObject& raw(const char* key, const std::string& json) {
    next(key);
    out_ << json;
    return *this;
  }
  JsonObject& indices(const char* key, const std::vector<Index>& values);
  JsonObject& pairs(const char* key, const std::vector<VertexPair>& values);
  std::string str() const { return out_.str() + "}"; }

 private:
  void next(const char* key) {
    out_ << (first_ ? "{" : ",") << "\"" << key << "\":";
    first_ = false;
  }
  std::ostringstream out_;
  bool first_ = true;
};

}  // namespace meshbridge::detail
