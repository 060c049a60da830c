// MSLB section (format 1.2): where a Metal app binds each block and sampler of the package's MSL,
// and the slots shader_abi.h pins for a material (what the compiler records and the reader expects).
#include <algorithm>
#include <set>
#include <string_view>

#include "facet/abi/shader_abi.h"
#include "sections.h"

namespace facet::package {

std::vector<MslBinding> mslBindingsFor(const MaterialInfo& material, bool shadowReceivers, bool irradianceCube) {
  std::vector<MslBinding> out;
  auto block = [&](const abi::BlockDesc& b) {
    out.push_back({std::string(b.name), MslResource::Buffer, b.set, b.binding, abi::mslBufferIndex(b)});
  };
  auto sampler = [&](std::string name, uint32_t set, uint32_t binding) {
    out.push_back({std::move(name), MslResource::Texture, set, binding, abi::mslTextureIndex(binding)});
  };
  block(abi::kFrameBlock);
  block(abi::kObjectBlock);
  if (material.paramBlockSize != 0) block(abi::kMaterialBlock);
  if (material.shading == "lit")
    for (const abi::SamplerDesc& s : abi::kFrameSamplers)
      if (irradianceCube || std::string_view(s.name) != abi::kIrradianceName)
        sampler(std::string(s.name), s.set, s.binding);
  // Only packages holding receivers (.sh, .sp1 variants) declare the shadow's block and atlas: the others'
  // bytes stay as they were.
  if (material.shading == "lit" && shadowReceivers) {
    block(abi::kShadowBlock);
    sampler(std::string(abi::kShadowAtlasSampler.name), abi::kShadowAtlasSampler.set, abi::kShadowAtlasSampler.binding);
  }
  for (const Param& p : material.params)
    if (isTexture(p.type) && p.offset != kNoTextureSlot)
      sampler(abi::kMaterialSamplerPrefix + p.name, abi::kTextureSet, abi::materialTextureBinding(p.offset));
  return out;
}

std::string mslBindingsError(const MaterialInfo& material, const std::vector<MslBinding>& bindings,
                             bool shadowReceivers) {
  if (bindings.empty()) return "";  // none recorded: a package before format 1.2
  // Whether a variant reads the irradiance cube is the tier's maths, which the package does not
  // record: its slot is pinned when listed and not required otherwise.
  const bool irradianceCube =
      std::any_of(bindings.begin(), bindings.end(), [](const MslBinding& b) { return b.name == abi::kIrradianceName; });
  const std::vector<MslBinding> pinned = mslBindingsFor(material, shadowReceivers, irradianceCube);
  for (const MslBinding& b : bindings) {
    const MslBinding* expected = nullptr;
    for (const MslBinding& p : pinned)
      if (p.name == b.name) expected = &p;
    const std::string slot = std::string(toString(b.kind)) + "(" + std::to_string(b.index) + ")";
    if (!expected)
      return "Metal binding '" + b.name + "' (" + slot + ") names no block or sampler of this material's shaders";
    if (b != *expected)
      return "Metal binding '" + b.name + "' is " + slot + " for Vulkan set " + std::to_string(b.set) + " binding " +
             std::to_string(b.binding) + "; the shader interface pins it at " + toString(expected->kind) + "(" +
             std::to_string(expected->index) + ") for set " + std::to_string(expected->set) + " binding " +
             std::to_string(expected->binding);
  }
  for (const MslBinding& p : pinned) {
    bool listed = false;
    for (const MslBinding& b : bindings) listed = listed || b.name == p.name;
    if (!listed) return "the Metal slots do not place '" + p.name + "', which the material's shaders declare";
  }
  return "";
}

}  // namespace facet::package

namespace facet::package::detail {

void encodeMslBindings(ByteWriter& out, const std::vector<MslBinding>& bindings) {
  out.u32(uint32_t(bindings.size()));
  for (const MslBinding& b : bindings) {
    out.string(b.name);
    out.u8(uint8_t(b.kind));
    out.u8(0);
    out.u16(0);
    out.u32(b.set);
    out.u32(b.binding);
    out.u32(b.index);
  }
}

void decodeMslBindings(ByteReader& in, std::vector<MslBinding>& bindings) {
  uint32_t count = in.count(kMinMslBindingSize, "Metal binding count");
  bindings.reserve(count);
  std::set<std::pair<MslResource, uint32_t>> slots;
  std::set<std::string> names;
  for (uint32_t i = 0; i < count && in.ok(); ++i) {
    const uint64_t at = in.position();
    MslBinding b;
    b.name = in.string("Metal binding name");
    const uint8_t kind = in.u8();
    const uint8_t reserved8 = in.u8();
    const uint16_t reserved16 = in.u16();
    b.set = in.u32();
    b.binding = in.u32();
    b.index = in.u32();
    if (!in.ok()) return;
    const std::string what = "Metal binding " + std::to_string(i) + " at byte " + std::to_string(at);
    if (!isGlslIdentifier(b.name, kMaxMslNameLength))
      return in.fail(what + " has a name that is not an identifier of 1.." + std::to_string(kMaxMslNameLength) +
                     " bytes");
    if (kind > kLastMslResource) return in.fail(what + " has unknown kind " + std::to_string(kind));
    if (reserved8 != 0 || reserved16 != 0) return in.fail(what + " has reserved bits set");
    b.kind = MslResource(kind);
    const uint32_t slotCount = b.kind == MslResource::Buffer ? kMslBufferSlots : kMslSamplerSlots;
    if (b.index >= slotCount)
      return in.fail(what + " ('" + b.name + "') uses " + toString(b.kind) + " slot " + std::to_string(b.index) +
                     "; Metal has " + std::to_string(slotCount));
    if (!names.insert(b.name).second) return in.fail(what + " names '" + b.name + "' a second time");
    if (!slots.insert({b.kind, b.index}).second)
      return in.fail(what + " ('" + b.name + "') reuses " + toString(b.kind) + " slot " + std::to_string(b.index));
    bindings.push_back(std::move(b));
  }
  in.expectEnd();
}

}  // namespace facet::package::detail
