// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// OpenMesh prints to its own error stream; a library call that expects refusals mutes it.

#include <OpenMesh/Core/System/omstream.hh>

namespace meshbridge::detail {

//! Mutes OpenMesh's error stream (omerr) for the guard's lifetime.
class MutedOpenMeshErrors {
 public:
  MutedOpenMeshErrors() : was_enabled_(omerr().is_enabled()) { omerr().disable(); }
  ~MutedOpenMeshErrors() {
    if (was_enabled_)
      omerr().enable();
  }
  MutedOpenMeshErrors(const MutedOpenMeshErrors&) = delete;
  MutedOpenMeshErrors& operator=(const MutedOpenMeshErrors&) = delete;

 private:
  bool was_enabled_;
};

}  // namespace meshbridge::detail
