// One SPIR-V module parsed by SPIRV-Cross's C API, with its compiler for one backend: the
// context is destroyed with the session, and every failure reads "SPIRV-Cross <step>: <reason>".
// Shared by the MSL backend and the interface reflection.
#pragma once

#include <spirv_cross_c.h>

#include <cstdint>
#include <string>
#include <vector>

namespace facet::compiler {

class SpirvCrossSession {
 public:
  SpirvCrossSession() = default;
  ~SpirvCrossSession() {
    if (context_) spvc_context_destroy(context_);
  }
  SpirvCrossSession(const SpirvCrossSession&) = delete;
  SpirvCrossSession& operator=(const SpirvCrossSession&) = delete;

  // Parses `words` and creates the backend's compiler. False with *error on failure.
  bool open(const std::vector<uint32_t>& words, spvc_backend backend, std::string* error) {
    if (spvc_context_create(&context_) != SPVC_SUCCESS) {
      context_ = nullptr;
      *error = "SPIRV-Cross: cannot create a context";
      return false;
    }
    spvc_parsed_ir ir = nullptr;
    if (spvc_context_parse_spirv(context_, words.data(), words.size(), &ir) != SPVC_SUCCESS)
      return fail("parse", error);
    if (spvc_context_create_compiler(context_, backend, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler_) !=
        SPVC_SUCCESS)
      return fail("create compiler", error);
    return true;
  }

  spvc_compiler compiler() const { return compiler_; }

  // Sets *error from the context's last error; returns false so callers can `return fail(...)`.
  bool fail(const char* step, std::string* error) const {
    *error = std::string("SPIRV-Cross ") + step + ": " + spvc_context_get_last_error_string(context_);
    return false;
  }

 private:
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
};

}  // namespace facet::compiler
