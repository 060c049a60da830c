#include "facet/compiler/msl_backend.h"

#include <spirv_cross_c.h>

namespace facet::compiler {

bool spirvToMsl(const std::vector<uint32_t>& words, std::string* msl, std::string* error) {
  spvc_context context = nullptr;
  if (spvc_context_create(&context) != SPVC_SUCCESS) {
    *error = "SPIRV-Cross: cannot create a context";
    return false;
  }
  auto fail = [&](const char* step) {
    *error = std::string("SPIRV-Cross ") + step + ": " + spvc_context_get_last_error_string(context);
    spvc_context_destroy(context);
    return false;
  };
  spvc_parsed_ir ir = nullptr;
  if (spvc_context_parse_spirv(context, words.data(), words.size(), &ir) != SPVC_SUCCESS) return fail("parse");
  spvc_compiler compiler = nullptr;
  if (spvc_context_create_compiler(context, SPVC_BACKEND_MSL, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler) != SPVC_SUCCESS)
    return fail("create compiler");
  spvc_compiler_options options = nullptr;
  if (spvc_compiler_create_compiler_options(compiler, &options) != SPVC_SUCCESS) return fail("options");
  spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_MSL_VERSION, SPVC_MAKE_MSL_VERSION(2, 0, 0));
  spvc_compiler_options_set_uint(options, SPVC_COMPILER_OPTION_MSL_PLATFORM, SPVC_MSL_PLATFORM_IOS);
  // Subpass inputs (the merged post pass) become [[color(n)]] framebuffer-fetch inputs, what
  // Apple's tile-based GPUs read without leaving tile memory. No effect on other shaders.
  spvc_compiler_options_set_bool(options, SPVC_COMPILER_OPTION_MSL_FRAMEBUFFER_FETCH_SUBPASS, SPVC_TRUE);
  if (spvc_compiler_install_compiler_options(compiler, options) != SPVC_SUCCESS) return fail("install options");
  const char* source = nullptr;
  if (spvc_compiler_compile(compiler, &source) != SPVC_SUCCESS) return fail("compile");
  *msl = source;
  spvc_context_destroy(context);
  return true;
}

}  // namespace facet::compiler
