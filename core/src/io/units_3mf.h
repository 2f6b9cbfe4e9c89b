// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 3MF model units (3MF Core Specification, section 3.4.1) as lib3mf 1.8 numbers them
// (eModelUnit) and as MeshAttributes::length_unit names them. Included by the 3MF reader and
// writer only (needs lib3mf's headers).

#include <Model/COM/NMR_DLLInterfaces.h>

#include <string>

namespace meshbridge::detail {

struct Unit3mf {
  DWORD unit;        //!< lib3mf's eModelUnit
  const char* name;  //!< the specification's name, MeshAttributes::length_unit
};

inline constexpr Unit3mf kUnits3mf[] = {{NMR::MODELUNIT_MICROMETER, "micron"},
                                        {NMR::MODELUNIT_MILLIMETER, "millimeter"},
                                        {NMR::MODELUNIT_CENTIMETER, "centimeter"},
                                        {NMR::MODELUNIT_INCH, "inch"},
                                        {NMR::MODELUNIT_FOOT, "foot"},
                                        {NMR::MODELUNIT_METER, "meter"}};

//! The name of lib3mf's unit `unit`; "millimeter" (3MF's default) for one it does not list.
inline const char* unit_name_3mf(DWORD unit) {
  for (const Unit3mf& u : kUnits3mf) {
    if (u.unit == unit)
      return u.name;
  }
  return "millimeter";
}

//! lib3mf's unit named `name`; millimetres for an empty or unknown name.
inline DWORD unit_3mf(const std::string& name) {
  for (const Unit3mf& u : kUnits3mf) {
    if (name == u.name)
      return u.unit;
  }
  return NMR::MODELUNIT_MILLIMETER;
}

}  // namespace meshbridge::detail
