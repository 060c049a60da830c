// MSLB section (format 1.2): where a Metal app binds each block and sampler of the package's MSL.
#include <set>

#include "sections.h"

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
      return in.fail(what + " has a name that is not an identifier of 1.." + std::to_string(kMaxMslNameLength) + " bytes");
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
