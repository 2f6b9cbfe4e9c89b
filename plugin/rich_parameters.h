// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file rich_parameters.h
//! The catalogue's parameters as MeshLab RichParameters. Header-only and written against the
//! RichBool / RichEnum / RichInt names both MeshLab generations share: each adapter includes it
//! after its own SDK's headers and names its length type (2020.09: RichAbsPerc, 2022+:
//! RichPercentage; both take name, value, min, max, label, tooltip).

#include "filter_catalog.h"

#include <QString>
#include <QStringList>

namespace meshbridge::meshlab {

//! Adds the parameters of filter `id` for a mesh of `faces` faces to `params` in dialog order.
//! Lengths range over [0, diagonal] (the mesh's bounding box diagonal, shown as a distance and a
//! percentage of it).
template <class RichLength, class Scalar, class ParameterList>
void add_rich_parameters(FilterId id, std::size_t faces, Scalar diagonal, ParameterList& params) {
  for (const ParameterSpec& p : parameters(id, faces)) {
    const QString tooltip = QString::fromStdString(p.tooltip);
    switch (p.kind) {
      case ParameterSpec::Kind::boolean:
        params.addParam(RichBool(p.name, p.bool_default, p.label, tooltip));
        break;
      case ParameterSpec::Kind::enumeration: {
        QStringList values;
        for (const char* v : p.enum_values)
          values << v;
        params.addParam(RichEnum(p.name, p.enum_default, values, p.label, tooltip));
        break;
      }
      case ParameterSpec::Kind::integer:
        params.addParam(RichInt(p.name, p.int_default, p.label, tooltip));
        break;
      case ParameterSpec::Kind::length:
        params.addParam(
            RichLength(p.name, Scalar(p.length_default), Scalar(0), diagonal, p.label, tooltip));
        break;
    }
  }
}

}  // namespace meshbridge::meshlab
