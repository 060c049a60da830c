// The memory row order of the frames the GL backend draws into its own targets (render()), and
// the two conversions that give it Vulkan's.
//
// GL's window y points up, so a GL target's memory row 0 is the picture's bottom; Vulkan's
// framebuffer y points down (vk_convert.h), so its row 0 is the top. Mesa's rasterizers (llvmpipe
// and lavapipe alike) take a 2×2 quad's derivatives, and so every implicit-LOD texture's level,
// from the quad's first row in memory (coarse derivatives, which GLSL ES 3.00 §8.9 and Vulkan's
// "Derivative Operations" allow): drawn in opposite row orders, the two APIs pick levels from
// different rows where a surface turns away at a grazing angle (docs/gltf.md, "Vulkan and GLES at
// silhouettes"). render() therefore draws its camera passes top-down, as Vulkan does: clip y
// negated, the front face swapped. Every later pass (MSAA resolve, bloom, post, FXAA) maps a
// memory row to the same memory row, so the image stays top-down to the readback, which takes
// the rows as they are. renderToFramebuffer() draws bottom-up, GL's convention for the app's
// framebuffer. The shadow atlas keeps GL's clip y in both (its coordinates are the receivers').
#pragma once

#include "facet/abi/shader_abi.h"

namespace facet::runtime::gl {

// Which of the two a pass draws in (the entry point decides: render() TopDown,
// renderToFramebuffer() BottomUp).
enum class RowOrder { TopDown, BottomUp };

// clip' = F · m, F negating y: the camera's view-projection (column-major 4×4, shader_abi.h) for a
// frame drawn top-down. A pixel's depth, and its orientation once the front face is swapped, are
// unchanged.
void topDownClip(const float gl[16], float out[16]);

// The background's block (abi::BackgroundParams) for a frame drawn top-down: the direction matrix
// takes the negated normalized device y its full-screen triangle is then drawn at (D · F), so
// each pixel sees the direction it sees bottom-up.
void topDownBackground(abi::BackgroundParams* params);

}  // namespace facet::runtime::gl
