#include "facet/compiler/spirv_tools_backend.h"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace facet::compiler {
namespace {

constexpr spv_target_env kEnv = SPV_ENV_VULKAN_1_0;

spvtools::MessageConsumer collectInto(std::string* log) {
  return [log](spv_message_level_t, const char*, const spv_position_t& position, const char* message) {
    *log += "word " + std::to_string(position.index) + ": " + message + "\n";
  };
}

}  // namespace

bool validateSpirv(const std::vector<uint32_t>& words, std::string* log) {
  spvtools::SpirvTools tools(kEnv);
  tools.SetMessageConsumer(collectInto(log));
  return tools.Validate(words);
}

bool optimizeSpirv(std::vector<uint32_t>* words, std::string* log) {
  spvtools::Optimizer optimizer(kEnv);
  optimizer.SetMessageConsumer(collectInto(log));
  optimizer.RegisterPerformancePasses();
  std::vector<uint32_t> optimized;
  if (!optimizer.Run(words->data(), words->size(), &optimized)) return false;
  *words = std::move(optimized);
  return true;
}

bool convertRelaxedToHalf(std::vector<uint32_t>* words, std::string* log) {
  spvtools::Optimizer optimizer(kEnv);
  optimizer.SetMessageConsumer(collectInto(log));
  optimizer.RegisterPass(spvtools::CreateConvertRelaxedToHalfPass());
  // The conversion leaves conversions between adjacent ops; the usual clean-up folds them.
  optimizer.RegisterPass(spvtools::CreateSimplificationPass());
  optimizer.RegisterPass(spvtools::CreateAggressiveDCEPass());
  std::vector<uint32_t> converted;
  if (!optimizer.Run(words->data(), words->size(), &converted)) return false;
  *words = std::move(converted);
  return true;
}

std::string disassembleSpirv(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(kEnv);
  std::string text;
  if (!tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES | SPV_BINARY_TO_TEXT_OPTION_INDENT))
    return "; (disassembly failed)\n";
  return text;
}

}  // namespace facet::compiler
