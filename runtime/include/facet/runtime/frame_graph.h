// A small frame graph: passes declare what they read, write and clear on virtual resources, and
// compile() derives what a tiled GPU needs to know: which passes share one render pass (as
// subpasses), each attachment's load and store operations, which attachments are transient, which
// passes can be dropped, and how many bytes the frame moves between tile memory and DRAM.
//
// Why (Guy's Filament mobile talk, on tilers): on a tiler a render target lives in on-chip tile
// memory while a render pass runs; loading it at the start and storing it at the end are the
// expensive DRAM transfers. A pass that reads only its own pixel of an earlier output (tone mapping, by
// framebuffer fetch or a subpass input) can run in the same render pass, so that output never
// leaves the tile. API-neutral: the Vulkan and GL backends turn the result into their own objects.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace facet::runtime::fg {

using ResourceId = uint32_t;

struct ResourceDesc {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t bytesPerPixel = 0;  // RGBA16F 8, RGBA8 4, D32 4, R11G11B10F 4
  bool depth = false;
  // Read after the frame by someone outside the graph (presented, read back): always stored.
  bool readAfterFrame = false;
  // Samples per pixel (MSAA): the bytes a load or store would move are samples × bytesPerPixel
  // per pixel. A multisampled attachment that is only resolved is transient: its samples stay in
  // tile memory and only the resolved image can reach DRAM.
  uint32_t samples = 1;
};

enum class ReadKind {
  OwnPixel,      // only the value at the pixel being shaded (framebuffer fetch, subpass input)
  WholeTexture,  // any texel (sampling, filtering, downsampling)
};

struct PassDesc {
  std::string name;
  std::vector<std::pair<ResourceId, ReadKind>> reads;
  std::vector<ResourceId> writes;  // render-target outputs (colour or depth)
  std::vector<ResourceId> clears;  // cleared at the start of the pass (and then written)
  // Single-sample images the pass's multisampled outputs are resolved into at its end (Vulkan
  // pResolveAttachments, GL glBlitFramebuffer). A resolve overwrites every pixel, so like a clear
  // it needs none of the image's earlier contents.
  std::vector<ResourceId> resolves;
};

enum class LoadOp { Load, Clear, DontCare };
enum class StoreOp { Store, DontCare };

// One resource's use as an attachment of one render pass.
struct Attachment {
  ResourceId resource = 0;
  LoadOp load = LoadOp::DontCare;
  StoreOp store = StoreOp::DontCare;
  bool inputAttachment = false;  // a later subpass of the same render pass reads its own pixel
};

struct RenderPass {
  std::vector<uint32_t> subpasses;  // pass indices, in order
  std::vector<Attachment> attachments;
};

// Memory traffic of one resource in one frame. Attachment loads and stores move the whole
// image; a WholeTexture read is counted as one read of every texel (a lower bound: filtering
// footprints and cache misses can read texels more than once).
struct ResourceTraffic {
  uint64_t loadedBytes = 0;
  uint64_t storedBytes = 0;
  uint64_t sampledBytes = 0;
  bool transient = false;  // never loaded or stored: can live in tile memory (lazily allocated)
};

struct CompiledGraph {
  std::vector<bool> culled;              // per pass
  std::vector<RenderPass> renderPasses;  // kept passes, grouped
  std::vector<ResourceTraffic> traffic;  // per resource
  uint64_t loadedBytes() const;
  uint64_t storedBytes() const;
  uint64_t sampledBytes() const;
  // The render pass and attachment of resource in it, or nullptr.
  const Attachment* attachment(uint32_t renderPass, ResourceId resource) const;
};

class FrameGraph {
 public:
  ResourceId addResource(ResourceDesc desc);
  uint32_t addPass(PassDesc desc);
  const ResourceDesc& resource(ResourceId id) const { return resources_[id]; }
  const PassDesc& pass(uint32_t index) const { return passes_[index]; }
  size_t resourceCount() const { return resources_.size(); }
  size_t passCount() const { return passes_.size(); }

  // Returns false and sets *error for a malformed graph (unknown resource ids, a pass reading a
  // resource nothing wrote before it, a clear that is not also an output).
  bool compile(CompiledGraph* out, std::string* error) const;

 private:
  std::vector<ResourceDesc> resources_;
  std::vector<PassDesc> passes_;
};

const char* toString(LoadOp op);
const char* toString(StoreOp op);

// A human-readable summary: render passes, their attachments and ops, and bytes per resource.
std::string describe(const FrameGraph& graph, const CompiledGraph& compiled);

}  // namespace facet::runtime::fg
