// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file pairing.h
//! How the contenders of an edge bridge are paired (DESIGN section 4).

namespace meshbridge {

//! Pairing policy for edges with more than two contenders.
enum class PairingPolicy {
  //! Sort contender faces by angle around the edge axis and pair cyclic neighbours whose wedge
  //! lies behind both faces; sheets (same region on both sides) are left over before solids are
  //! broken; the rest pair by elimination. Needs positions; falls back to `combinatorial`
  //! for faces without a usable normal.
  geometric,
  //! Opposite-running sides first, in face order; then the rest in face order.
  combinatorial,
};

}  // namespace meshbridge
