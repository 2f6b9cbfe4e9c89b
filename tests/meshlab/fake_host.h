// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A MeshLab document without MeshLab, for the adapter's tests: the defect layer is kept here.

#include "filter_actions.h"

#include <string>
#include <utility>

//! A document without MeshLab: the defect layer is kept here (per-face colour enabled when asked
//! for), the layer's file name is given.
class FakeHost final : public meshbridge::meshlab::DocumentHost {
 public:
  explicit FakeHost(std::string file_name) : file_name_(std::move(file_name)) {}
  void enable_face_color() override {}
  CMeshO& add_defect_layer(const std::string&, bool face_color) override {
    layer_.Clear();
    if (face_color && !layer_.face.IsColorEnabled())
      layer_.face.EnableColor();
    return layer_;
  }
  std::size_t remove_layers(const std::string&) override { return 0; }
  bool can_save_3mf() const override { return false; }
  std::string file_name() const override { return file_name_; }
  const CMeshO& layer() const { return layer_; }

 private:
  std::string file_name_;
  CMeshO layer_;
};
