#include "facet/runtime/frame_graph.h"

#include <algorithm>
#include <cstdio>
#include <set>

namespace facet::runtime::fg {
namespace {

uint64_t imageBytes(const ResourceDesc& r) {
  return uint64_t{r.width} * r.height * r.bytesPerPixel * std::max<uint32_t>(r.samples, 1);
}

bool contains(const std::vector<ResourceId>& ids, ResourceId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Outputs of a pass: what it writes, clears or resolves into.
std::vector<ResourceId> outputsOf(const PassDesc& pass) {
  std::vector<ResourceId> out = pass.writes;
  for (const std::vector<ResourceId>* more : {&pass.clears, &pass.resolves}) {
    for (ResourceId id : *more) {
      if (!contains(out, id)) out.push_back(id);
    }
  }
  return out;
}

// Outputs whose earlier contents the pass does not need: cleared or resolved into.
bool overwrites(const PassDesc& pass, ResourceId id) {
  return contains(pass.clears, id) || contains(pass.resolves, id);
}

bool sameSize(const ResourceDesc& a, const ResourceDesc& b) { return a.width == b.width && a.height == b.height; }

}  // namespace

ResourceId FrameGraph::addResource(ResourceDesc desc) {
  resources_.push_back(std::move(desc));
  return static_cast<ResourceId>(resources_.size() - 1);
}

uint32_t FrameGraph::addPass(PassDesc desc) {
  passes_.push_back(std::move(desc));
  return static_cast<uint32_t>(passes_.size() - 1);
}

uint64_t CompiledGraph::loadedBytes() const {
  uint64_t sum = 0;
  for (const ResourceTraffic& t : traffic) sum += t.loadedBytes;
  return sum;
}

uint64_t CompiledGraph::storedBytes() const {
  uint64_t sum = 0;
  for (const ResourceTraffic& t : traffic) sum += t.storedBytes;
  return sum;
}

uint64_t CompiledGraph::sampledBytes() const {
  uint64_t sum = 0;
  for (const ResourceTraffic& t : traffic) sum += t.sampledBytes;
  return sum;
}

const Attachment* CompiledGraph::attachment(uint32_t renderPass, ResourceId resource) const {
  if (renderPass >= renderPasses.size()) return nullptr;
  for (const Attachment& a : renderPasses[renderPass].attachments) {
    if (a.resource == resource) return &a;
  }
  return nullptr;
}

bool FrameGraph::compile(CompiledGraph* out, std::string* error) const {
  const size_t resourceCount = resources_.size();
  // Validation: ids in range, clears are outputs, reads follow a write.
  std::vector<bool> written(resourceCount, false);
  for (const PassDesc& pass : passes_) {
    auto bad = [&](ResourceId id) { return id >= resourceCount; };
    for (const auto& read : pass.reads) {
      if (bad(read.first)) {
        *error = "pass '" + pass.name + "' reads unknown resource " + std::to_string(read.first);
        return false;
      }
      if (!written[read.first]) {
        *error = "pass '" + pass.name + "' reads '" + resources_[read.first].name + "' before any pass writes it";
        return false;
      }
    }
    for (ResourceId id : outputsOf(pass)) {
      if (bad(id)) {
        *error = "pass '" + pass.name + "' writes unknown resource " + std::to_string(id);
        return false;
      }
      written[id] = true;
    }
  }

  CompiledGraph g;
  const size_t passCount = passes_.size();
  g.culled.assign(passCount, true);
  g.traffic.assign(resourceCount, ResourceTraffic{});

  // Culling, last pass first: a pass is kept when one of its outputs is needed later. A pass
  // that writes without clearing blends into (or only partly covers) what was there, so it needs
  // the earlier contents too; a clear ends that need.
  std::set<ResourceId> live;
  for (ResourceId id = 0; id < resourceCount; ++id) {
    if (resources_[id].readAfterFrame) live.insert(id);
  }
  for (size_t i = passCount; i-- > 0;) {
    const PassDesc& pass = passes_[i];
    const std::vector<ResourceId> outputs = outputsOf(pass);
    const bool needed = std::any_of(outputs.begin(), outputs.end(), [&](ResourceId id) { return live.count(id) != 0; });
    if (!needed) continue;
    g.culled[i] = false;
    for (ResourceId id : outputs) {
      if (overwrites(pass, id)) live.erase(id);
    }
    for (ResourceId id : pass.writes) {
      if (!overwrites(pass, id)) live.insert(id);
    }
    for (const auto& read : pass.reads) live.insert(read.first);
  }

  // Grouping: a kept pass joins the current render pass when everything it reads is the own
  // pixel of an attachment of that render pass, and its outputs have the same size (one tile
  // grid). Otherwise it starts a new render pass, and the outputs it reads must go to memory.
  std::vector<uint32_t> renderPassOf(passCount, UINT32_MAX);
  for (uint32_t i = 0; i < passCount; ++i) {
    if (g.culled[i]) continue;
    const PassDesc& pass = passes_[i];
    bool merge = !g.renderPasses.empty() && !pass.reads.empty();
    if (merge) {
      const RenderPass& current = g.renderPasses.back();
      const ResourceDesc& reference = resources_[current.attachments.front().resource];
      for (const auto& read : pass.reads) {
        const bool attached = std::any_of(current.attachments.begin(), current.attachments.end(),
                                          [&](const Attachment& a) { return a.resource == read.first; });
        if (read.second != ReadKind::OwnPixel || !attached) merge = false;
      }
      for (ResourceId id : outputsOf(pass)) {
        if (!sameSize(resources_[id], reference)) merge = false;
      }
    }
    if (!merge) g.renderPasses.push_back(RenderPass{});
    RenderPass& rp = g.renderPasses.back();
    rp.subpasses.push_back(i);
    renderPassOf[i] = static_cast<uint32_t>(g.renderPasses.size() - 1);
    for (ResourceId id : outputsOf(pass)) {
      const bool present = std::any_of(rp.attachments.begin(), rp.attachments.end(),
                                       [&](const Attachment& a) { return a.resource == id; });
      if (present) continue;
      Attachment a;
      a.resource = id;
      rp.attachments.push_back(a);
    }
    if (merge) {
      for (const auto& read : pass.reads) {
        for (Attachment& a : rp.attachments) {
          if (a.resource == read.first) a.inputAttachment = true;
        }
      }
    }
  }

  // Load and store operations, and traffic.
  std::vector<bool> hasContents(resourceCount, false);  // written by an earlier render pass
  for (uint32_t k = 0; k < g.renderPasses.size(); ++k) {
    RenderPass& rp = g.renderPasses[k];
    for (Attachment& a : rp.attachments) {
      // The first subpass touching the attachment decides the load.
      for (uint32_t p : rp.subpasses) {
        const PassDesc& pass = passes_[p];
        if (contains(pass.clears, a.resource)) {
          a.load = LoadOp::Clear;
          break;
        }
        if (contains(pass.resolves, a.resource)) {
          a.load = LoadOp::DontCare;
          break;
        }
        if (contains(pass.writes, a.resource)) {
          a.load = hasContents[a.resource] ? LoadOp::Load : LoadOp::DontCare;
          break;
        }
      }
      // Stored when read after the frame, or used by a later render pass (sampled, loaded).
      bool usedLater = resources_[a.resource].readAfterFrame;
      for (uint32_t p = rp.subpasses.back() + 1; p < passCount && !usedLater; ++p) {
        if (g.culled[p]) continue;
        const PassDesc& later = passes_[p];
        for (const auto& read : later.reads) usedLater |= read.first == a.resource;
        usedLater |= contains(later.writes, a.resource) && !overwrites(later, a.resource);
      }
      a.store = usedLater ? StoreOp::Store : StoreOp::DontCare;
      ResourceTraffic& t = g.traffic[a.resource];
      const uint64_t bytes = imageBytes(resources_[a.resource]);
      if (a.load == LoadOp::Load) t.loadedBytes += bytes;
      if (a.store == StoreOp::Store) t.storedBytes += bytes;
    }
    for (const Attachment& a : rp.attachments) hasContents[a.resource] = true;
    // Reads that are not input attachments of this render pass come from memory.
    for (uint32_t p : rp.subpasses) {
      for (const auto& read : passes_[p].reads) {
        const Attachment* a = g.attachment(k, read.first);
        if (!a || !a->inputAttachment) g.traffic[read.first].sampledBytes += imageBytes(resources_[read.first]);
      }
    }
  }
  for (ResourceId id = 0; id < resourceCount; ++id) {
    ResourceTraffic& t = g.traffic[id];
    bool attached = false;
    for (const RenderPass& rp : g.renderPasses) {
      for (const Attachment& a : rp.attachments) attached |= a.resource == id;
    }
    t.transient = attached && t.loadedBytes == 0 && t.storedBytes == 0 && t.sampledBytes == 0;
  }
  *out = std::move(g);
  return true;
}

const char* toString(LoadOp op) {
  switch (op) {
    case LoadOp::Load: return "load";
    case LoadOp::Clear: return "clear";
    case LoadOp::DontCare: return "dont_care";
  }
  return "?";
}

const char* toString(StoreOp op) { return op == StoreOp::Store ? "store" : "dont_care"; }

std::string describe(const FrameGraph& graph, const CompiledGraph& compiled) {
  std::string text;
  char line[256];
  for (size_t k = 0; k < compiled.renderPasses.size(); ++k) {
    const RenderPass& rp = compiled.renderPasses[k];
    text += "render pass " + std::to_string(k) + ":";
    for (uint32_t p : rp.subpasses) text += " " + graph.pass(p).name;
    text += "\n";
    for (const Attachment& a : rp.attachments) {
      std::snprintf(line, sizeof line, "  %-10s load %-9s store %-9s%s\n", graph.resource(a.resource).name.c_str(),
                    toString(a.load), toString(a.store), a.inputAttachment ? " (input attachment)" : "");
      text += line;
    }
  }
  for (size_t i = 0; i < compiled.culled.size(); ++i) {
    if (compiled.culled[i]) text += "culled: " + graph.pass(static_cast<uint32_t>(i)).name + "\n";
  }
  for (ResourceId id = 0; id < graph.resourceCount(); ++id) {
    const ResourceTraffic& t = compiled.traffic[id];
    const ResourceDesc& r = graph.resource(id);
    const std::string name = r.samples > 1 ? r.name + " " + std::to_string(r.samples) + "x" : r.name;
    std::snprintf(line, sizeof line, "  %-10s loaded %10llu B  stored %10llu B  sampled %10llu B%s\n", name.c_str(),
                  static_cast<unsigned long long>(t.loadedBytes), static_cast<unsigned long long>(t.storedBytes),
                  static_cast<unsigned long long>(t.sampledBytes), t.transient ? "  transient" : "");
    text += line;
  }
  std::snprintf(line, sizeof line, "total: loaded %llu B, stored %llu B, sampled %llu B per frame\n",
                static_cast<unsigned long long>(compiled.loadedBytes()),
                static_cast<unsigned long long>(compiled.storedBytes()),
                static_cast<unsigned long long>(compiled.sampledBytes()));
  text += line;
  return text;
}

}  // namespace facet::runtime::fg
