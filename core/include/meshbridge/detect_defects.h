// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file detect_defects.h
//! Detection alone: no geometry changes.

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

namespace meshbridge {

//! Finds every defect listed in DefectReport.
//!
//! Zero-area: twice the polygon's vector area is at most 1e-12 times the sum of its squared
//! side lengths (scale-free; exact zero for collinear integer input).
//! Singular vertices: a vertex on a singular edge, or one whose polygons fall into more than one
//! fan through its 2-sided edges.
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element
DefectReport detect_defects(const Soup& soup);

}  // namespace meshbridge
