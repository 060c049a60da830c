#include "untrusted_spirv.h"

#include <spirv-tools/libspirv.hpp>

namespace facet::package {

bool validateUntrustedSpirv(const std::vector<uint32_t>& words, std::string* error) {
  if (words.empty()) {
    *error = "empty SPIR-V module";
    return false;
  }
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
  std::string first;
  tools.SetMessageConsumer(
      [&first](spv_message_level_t, const char*, const spv_position_t& position, const char* message) {
        if (first.empty())
          first = "word " + std::to_string(position.index) + ": " + std::string(message).substr(0, 300);
      });
  if (tools.Validate(words)) return true;
  *error = "invalid SPIR-V (" + (first.empty() ? std::string("rejected by spirv-val") : first) + ")";
  return false;
}

}  // namespace facet::package
