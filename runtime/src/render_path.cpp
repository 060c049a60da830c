#include "facet/runtime/render_path.h"

namespace facet::runtime {

const char* toString(PostPath path) {
  switch (path) {
    case PostPath::Auto: return "auto";
    case PostPath::Merged: return "merged";
    case PostPath::Separate: return "separate";
  }
  return "?";
}

const char* toString(HdrFormat format) { return format == HdrFormat::R11G11B10Float ? "r11g11b10f" : "rgba16f"; }

uint32_t bytesPerPixel(HdrFormat format) { return format == HdrFormat::R11G11B10Float ? 4 : 8; }

ForwardPostGraph buildForwardPostGraph(uint32_t width, uint32_t height, PostPath path, bool readBackHdr,
                                       HdrFormat hdrFormat) {
  ForwardPostGraph g;
  g.hdr = g.graph.addResource({"hdr", width, height, bytesPerPixel(hdrFormat), false, readBackHdr});
  g.depth = g.graph.addResource({"depth", width, height, 4, true, false});
  g.ldr = g.graph.addResource({"ldr", width, height, 4, false, true});
  g.forwardPass = g.graph.addPass({"forward", {}, {g.hdr, g.depth}, {g.hdr, g.depth}});
  const fg::ReadKind read = path == PostPath::Separate ? fg::ReadKind::WholeTexture : fg::ReadKind::OwnPixel;
  g.postPass = g.graph.addPass({"post", {{g.hdr, read}}, {g.ldr}, {}});
  return g;
}

}  // namespace facet::runtime
