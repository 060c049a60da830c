// A scene prepared for rendering with a package built from a configuration that may differ from
// its tier's preset (a `matc eval` swap). runtime::SceneFrame prepares by the tier's *preset*:
// the colour encoding of parameters and sRGB textures (the gamma hack lights sRGB-encoded values)
// follows the preset, since an app only ever ships presets. This makes the frame match the
// configuration instead; runtime/ is left as it is. (The DFG table also follows the preset; every
// preset's ambient is split-sum, so it is bound for every tier, and a swap to an
// ambient model without the table leaves it unused.)
#pragma once

#include <deque>
#include <map>
#include <memory>
#include <string>

#include "facet/permutations/tiers.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"

namespace facet::eval {

class PreparedFrame {
 public:
  // The scene's `tier` picks the variant of `<packageDir>/<material>.matpkg`, whose shaders were
  // built with `config`. Nullptr with *error on any problem SceneFrame::prepare reports.
  static std::unique_ptr<PreparedFrame> prepare(const runtime::Scene& scene, const std::string& packageDir,
                                                const permutations::TierConfig& config, std::string* error);

  const runtime::FrameDesc& frame() const { return frame_; }
  double exposure() const { return scene_->exposure(); }  // what light values were multiplied by

 private:
  PreparedFrame() = default;
  bool adapt(const runtime::Scene& scene, const std::string& packageDir, const permutations::TierConfig& preset,
             const permutations::TierConfig& config, std::string* error);
  const runtime::Texture* recoded(const runtime::Texture* texture, bool srgbEncodedInShader);

  std::unique_ptr<runtime::SceneFrame> scene_;  // owns what frame_ points to, with textures_
  runtime::FrameDesc frame_;
  std::deque<runtime::Texture> textures_;
  std::map<std::pair<const runtime::Texture*, runtime::TextureFormat>, const runtime::Texture*> copies_;
};

}  // namespace facet::eval
