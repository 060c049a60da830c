// The API-neutral description of one frame, and the interface each graphics backend implements.
//
// A backend receives everything already resolved: meshes as interleaved vertices, uniform block
// bytes in std140, and shader code for its API. It knows nothing about packages or scenes.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "facet/shader_abi.h"

namespace facet::runtime {

struct Mesh {
  std::vector<float> vertices;   // abi::kVertexFloats per vertex: position.xyz, normal.xyz, uv0.xy
  std::vector<uint32_t> indices; // triangle list
};

// Shader code of one material variant, one field per API.
struct ShaderProgram {
  std::vector<uint32_t> vertexSpirv;    // Vulkan flavour, SPIR-V 1.0 words
  std::vector<uint32_t> fragmentSpirv;
  std::string vertexGlslEs;             // GLES flavour, "#version 300 es" source text
  std::string fragmentGlslEs;
};

struct DrawItem {
  const Mesh* mesh = nullptr;
  const ShaderProgram* program = nullptr;
  abi::ObjectUniforms object{};
  std::vector<uint8_t> materialParams;  // std140 bytes of block "MaterialParams" (may be empty)
};

struct FrameDesc {
  uint32_t width = 0;
  uint32_t height = 0;
  abi::FrameUniforms frame{};
  float clearColor[4] = {0, 0, 0, 1};   // linear, pre-exposed HDR value
  std::vector<DrawItem> draws;
};

struct FrameResult {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> ldr;  // RGBA8, rows top to bottom: the post pass output (tone mapped, sRGB-encoded)
  std::vector<float> hdr;    // RGBA float, rows top to bottom: the forward pass output (RGBA16F target)
};

class RenderBackend {
 public:
  virtual ~RenderBackend() = default;
  virtual const char* name() const = 0;
  // Renders the frame: forward pass into an RGBA16F target with depth, then the post pass into
  // RGBA8. Returns false and sets *error on failure; never throws, never aborts.
  virtual bool render(const FrameDesc& frame, FrameResult* result, std::string* error) = 0;
  // Messages of severity error reported by the API's validation (Vulkan validation layers,
  // GL debug output). Tests require this to be empty.
  virtual const std::vector<std::string>& validationErrors() const = 0;
};

struct VulkanOptions {
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation and collect its errors
};

// Each returns nullptr and sets *error when the API is unavailable (no device, no driver).
std::unique_ptr<RenderBackend> createVulkanBackend(const VulkanOptions& options, std::string* error);
std::unique_ptr<RenderBackend> createGlBackend(std::string* error);

// Shaders of the post pass (templates/post_*.glsl), compiled at build time.
struct PostShaders {
  const std::vector<uint32_t>& vertexSpirv;
  const std::vector<uint32_t>& fragmentSpirv;
  const std::string& vertexGlslEs;
  const std::string& fragmentGlslEs;
};
const PostShaders& postShaders();

}  // namespace facet::runtime
