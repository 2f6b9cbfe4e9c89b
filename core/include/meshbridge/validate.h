// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file validate.h
//! Preconditions every algorithm checks on entry.

#include "meshbridge/soup.h"

namespace meshbridge {

//! Checks that every index is in range, every polygon has at least 3 corners and every
//! coordinate is finite. Repeated vertex indices are allowed (they are reported, not rejected).
//! \throw InvalidSoupError whose message names the face, corner or vertex
void validate_soup(const Soup& soup);

}  // namespace meshbridge
