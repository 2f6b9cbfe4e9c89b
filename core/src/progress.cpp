// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/progress.h"

namespace meshbridge {

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::read:
      return "read";
    case Stage::group:
      return "group";
    case Stage::pair:
      return "pair";
    case Stage::detect:
      return "detect";
    case Stage::write:
      return "write";
  }
  return "?";
}

}  // namespace meshbridge
