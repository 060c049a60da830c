// createGlBackend(GlOptions) of render_backend.h: the GL backend on a headless context of its own.
#include "facet/runtime/gl_backend.h"
#include "headless_context.h"

namespace facet::runtime {

std::unique_ptr<RenderBackend> createGlBackend(const GlOptions& options, std::string* error) {
  std::unique_ptr<GlContext> context = gl::createHeadlessContext(options.context, error);
  if (!context) return nullptr;
  return createGlBackend(std::move(context), options, error);
}

std::unique_ptr<RenderBackend> createGlBackend(std::string* error) { return createGlBackend(GlOptions{}, error); }

}  // namespace facet::runtime
