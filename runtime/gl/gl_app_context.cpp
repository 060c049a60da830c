// The app's current GL context behind GlContext: entry points from the app's getProcAddress,
// never made current or destroyed by the backend, only checked to be the current one.
#include <utility>

#include "facet/runtime/gl_backend.h"

namespace facet::runtime {
namespace {

class AppContext final : public GlContext {
 public:
  explicit AppContext(GlAppContext app) : app_(std::move(app)) {}

  // Remembers which context is current now, so makeCurrent can tell when another one is.
  bool adopt(std::string* error) {
    if (!app_.getProcAddress) {
      if (error) *error = "GlAppContext::getProcAddress is required (eglGetProcAddress, SDL_GL_GetProcAddress, ...)";
      return false;
    }
    if (app_.currentContext) {
      handle_ = app_.currentContext();
      if (!handle_) {
        if (error) *error = "no GL context is current on this thread: make the app's OpenGL ES 3 context current first";
        return false;
      }
    }
    return true;
  }

  void* getProcAddress(const char* name) override { return app_.getProcAddress(name); }
  bool makeCurrent(std::string* error) override {
    if (app_.currentContext && app_.currentContext() != handle_) {
      if (error) *error = "the app's GL context is not current on this thread";
      return false;
    }
    return true;
  }
  const char* name() const override { return "app GL"; }
  bool backendOwnsDebugOutput() const override { return false; }

 private:
  GlAppContext app_;
  void* handle_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> adoptGlContext(GlAppContext app, std::string* error) {
  auto context = std::make_unique<AppContext>(std::move(app));
  if (!context->adopt(error)) return nullptr;
  return context;
}

std::unique_ptr<GlRenderer> createGlBackend(const GlAppContext& app, const GlOptions& options, std::string* error) {
  std::unique_ptr<GlContext> context = adoptGlContext(app, error);
  if (!context) return nullptr;
  return createGlBackend(std::move(context), options, error);
}

}  // namespace facet::runtime
