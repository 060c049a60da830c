// Evaluates GLSL functions on the GPU (lavapipe): the chunk tests' harness, and `matc eval`'s
// BRDF-domain sweep (brdf_sweep.h).
//
// One compute shader per call: `#version 310 es`, the given default float precision, the chunk
// sources in order, then a body that reads `vec4 in0, in1` and writes `vec4 result`, once per
// input. Compiled with glslang, run on a Vulkan 1.1 device set up by the runtime's own Vulkan
// context (runtime/vulkan/vk_context.h: the instance, device choice and validation layers the
// Vulkan backend uses), a device of its own or the app's. With FACET_VK_VALIDATION set (as the
// runtime reads it) the Khronos validation layer, synchronization validation included, is enabled
// and any validation error fails the call.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace facet::runtime {
struct AppDevice;  // facet/runtime/vulkan_backend.h
}

namespace facet::eval {

enum class FloatPrecision { Highp, Mediump };

// An R8 UNORM 2D texture bound as `uniform mediump sampler2D lut` (linear filtering, clamp to edge,
// one mip), for chunks that read a table.
struct GpuR8Texture {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> texels;  // row-major
};

struct GpuEvalRequest {
  std::vector<std::string> chunks;  // GLSL function sources, pasted in order
  std::string body;                 // statements computing `result` from `in0`, `in1`
  std::vector<glm::vec4> in0, in1;  // one invocation per element; same size
  FloatPrecision precision = FloatPrecision::Highp;
  // in0 and in1 declared highp whatever `precision` says (inputs a shader forms at highp, e.g.
  // geometry); otherwise they are at the default precision (rounded to binary16 under fp16
  // emulation, as a mediump input would be).
  bool highpInputs = false;
  const GpuR8Texture* lut = nullptr;
  // Optional: rewrites glslang's unoptimized SPIR-V (1.3, Vulkan 1.1) before the pipeline is
  // created, e.g. a SPIR-V pass under test. Returning false fails the call with *error.
  std::function<bool(std::vector<uint32_t>* spirv, std::string* error)> transformSpirv;
};

struct GpuEvalResult {
  std::vector<glm::vec4> values;  // one per input
  std::string error;              // compile log, Vulkan failure or validation messages
  bool ok() const { return error.empty(); }
};

class GpuEvaluator {
 public:
  // Creates an instance and device as the Vulkan backend does; check ready(). Validation: the
  // Khronos layer on, any error fails the call (also on with FACET_VK_VALIDATION).
  explicit GpuEvaluator(bool validation = false);
  // Runs on the app's instance, device and queue (as createVulkanBackend(AppDevice) does: the
  // queue family must also run compute work; the device must outlive the evaluator, which
  // destroys none of it). Validation is the app's instance's business: its layers report to the
  // app's messenger, not to GpuEvalResult::error.
  explicit GpuEvaluator(const runtime::AppDevice& device);
  ~GpuEvaluator();
  GpuEvaluator(const GpuEvaluator&) = delete;
  GpuEvaluator& operator=(const GpuEvaluator&) = delete;

  bool ready() const;
  const std::string& initError() const;
  std::string deviceName() const;

  GpuEvalResult run(const GpuEvalRequest& request);

  // The full compute shader source a request turns into (for failure messages).
  static std::string shaderSource(const GpuEvalRequest& request);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facet::eval
