// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file meshlab_document_host.h
//! The MeshLab document as the shared detect filter sees it. Header-only and written against
//! the MeshDocument / MeshModel names both MeshLab generations share: each adapter includes it
//! after its own SDK's headers (the two adapters are never compiled together).

#include "filter_actions.h"

#include <string>

namespace meshbridge::meshlab {

class MeshDocumentHost final : public DetectHost {
 public:
  explicit MeshDocumentHost(MeshDocument& md) : md_(md), mesh_(*md.mm()) {}
  void enable_face_colour() override { mesh_.updateDataMask(MeshModel::MM_FACECOLOR); }
  CMeshO& add_defect_layer(const std::string& label) override {
    MeshModel* layer = md_.addNewMesh("", QString::fromStdString(label), false);
    layer->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);
    return layer->cm;
  }

 private:
  MeshDocument& md_;
  MeshModel& mesh_;
};

}  // namespace meshbridge::meshlab
