#include "facet/compiler/glslang_backend.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>
#include <mutex>
#include <tuple>

namespace facet::compiler {
namespace {

void initializeOnce() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

struct Target {
  bool vulkan;
  int version;  // 310 for Vulkan, 300 for OpenGL ES
};

std::unique_ptr<glslang::TShader> parseStage(EShLanguage stage, const std::string& text, Target target,
                                             std::string* log) {
  auto shader = std::make_unique<glslang::TShader>(stage);
  const char* strings[] = {text.c_str()};
  shader->setStrings(strings, 1);
  EShMessages messages = EShMsgDefault;
  if (target.vulkan) {
    shader->setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
    shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
  }
  if (!shader->parse(GetDefaultResources(), target.version, EEsProfile, false, false, messages)) {
    *log += std::string(stage == EShLangVertex ? "vertex" : "fragment") + " stage:\n" + shader->getInfoLog();
    return nullptr;
  }
  return shader;
}

// Parses both stages and links them; the shaders must outlive the program.
bool parseAndLink(const StageSources& s, Target target, std::unique_ptr<glslang::TShader>* vs,
                  std::unique_ptr<glslang::TShader>* fs, glslang::TProgram* program, std::string* log) {
  initializeOnce();
  *vs = parseStage(EShLangVertex, s.vertex, target, log);
  *fs = parseStage(EShLangFragment, s.fragment, target, log);
  if (!*vs || !*fs) return false;
  program->addShader(vs->get());
  program->addShader(fs->get());
  EShMessages messages = target.vulkan ? EShMessages(EShMsgSpvRules | EShMsgVulkanRules) : EShMsgDefault;
  if (!program->link(messages)) {
    *log += std::string("link:\n") + program->getInfoLog();
    return false;
  }
  return true;
}

}  // namespace

bool compileToSpirv(const StageSources& sources, SpirvStages* out, std::string* log) {
  std::unique_ptr<glslang::TShader> vs, fs;
  glslang::TProgram program;
  if (!parseAndLink(sources, {true, 310}, &vs, &fs, &program, log)) return false;
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // spirv-opt runs as its own, validated step
  options.validate = false;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangVertex), out->vertex, &logger, &options);
  glslang::GlslangToSpv(*program.getIntermediate(EShLangFragment), out->fragment, &logger, &options);
  std::string messages = logger.getAllMessages();
  if (!messages.empty()) *log += messages;
  return !out->vertex.empty() && !out->fragment.empty();
}

bool preprocessGlslEs300(const StageSources& sources, StageSources* out, std::string* log) {
  initializeOnce();
  for (auto [stage, in, result] : {std::tuple{EShLangVertex, &sources.vertex, &out->vertex},
                                   std::tuple{EShLangFragment, &sources.fragment, &out->fragment}}) {
    glslang::TShader shader(stage);
    const char* strings[] = {in->c_str()};
    shader.setStrings(strings, 1);
    glslang::TShader::ForbidIncluder includer;
    if (!shader.preprocess(GetDefaultResources(), 300, EEsProfile, false, false, EShMsgDefault, result, includer)) {
      *log += std::string(stage == EShLangVertex ? "vertex" : "fragment") + " stage:\n" + shader.getInfoLog();
      return false;
    }
  }
  out->fragmentSurfaceLine = 0;
  return true;
}

bool checkGlslEs300(const StageSources& sources, std::string* log) {
  std::unique_ptr<glslang::TShader> vs, fs;
  glslang::TProgram program;
  return parseAndLink(sources, {false, 300}, &vs, &fs, &program, log);
}

}  // namespace facet::compiler
