// The GL backend (OSMesa, llvmpipe) runs "#version 300 es" shaders and honours the shader ABI.
// OSMesa is a hard dependency of the project: when it is missing these tests fail, not skip.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <EGL/egl.h>

#include "facet/runtime/frame_eviction.h"
#include "facet/runtime/gl_backend.h"
#include "facet/runtime/mesh.h"
#include "facet/runtime/render_backend.h"
#include "gl_context.h"
#include "gl_test_interface.h"
#include "headless_context.h"

namespace facet::runtime {
namespace {

constexpr const char* kVertexShader = "#version 300 es\n" FACET_GL_TEST_VERTEX_INTERFACE R"(out vec2 vUv;
void main() {
  vUv = )" FACET_GL_TEST_UV0 R"( + normal.xy * 0.0;
  vec4 objectPosition = vec4()" FACET_GL_TEST_POSITION R"(, 1.0);
  gl_Position = viewProjection * )" FACET_GL_TEST_WORLD("objectPosition") R"(;
}
)";

// Colour = baseColor + emissive, both from the material block.
constexpr const char* kMaterialFragmentShader = R"(#version 300 es
precision highp float;
layout(std140) uniform MaterialParams {
  vec4 baseColor;
  vec4 emissive;
};
in vec2 vUv;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = baseColor + emissive; }
)";

// Colour = lightColor from the frame block; no material block at all.
constexpr const char* kLightColourFragmentShader =
    "#version 300 es\nprecision highp float;\n" FACET_GL_TEST_FRAME_BLOCK R"(layout(location = 0) out vec4 fragColor;
void main() { fragColor = lightColor; }
)";

constexpr const char* kBrokenFragmentShader = R"(#version 300 es
precision highp float;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = this is not glsl; }
)";

struct Rgba {
  float r, g, b, a;
};

void setIdentity(float* m) {
  std::memset(m, 0, 16 * sizeof(float));
  m[0] = m[5] = m[10] = m[15] = 1.0f;
}

// A translation: the last column of the instance's rows.
abi::InstanceTransform translation(float x, float y, float z) {
  abi::InstanceTransform t = kIdentityInstance;
  t.rows[0][3] = x;
  t.rows[1][3] = y;
  t.rows[2][3] = z;
  return t;
}

FrameDesc makeFrame(uint32_t width, uint32_t height) {
  FrameDesc frame;
  frame.width = width;
  frame.height = height;
  setIdentity(frame.frame.viewProjection);
  return frame;
}

DrawItem makeDraw(const Mesh& mesh, const ShaderProgram& program) {
  DrawItem draw;
  draw.mesh = &mesh;
  draw.program = &program;
  draw.instances = {kIdentityInstance};
  return draw;
}

void addVertex(Mesh* mesh, float x, float y, float z) { appendVertex(*mesh, Vertex{{x, y, z}}); }

Mesh triangle(float x0, float y0, float x1, float y1, float x2, float y2, float z = 0.0f) {
  Mesh mesh;
  addVertex(&mesh, x0, y0, z);
  addVertex(&mesh, x1, y1, z);
  addVertex(&mesh, x2, y2, z);
  mesh.indices = {0, 1, 2};
  return mesh;
}

Mesh quad(float x0, float y0, float x1, float y1, float z) {
  Mesh mesh;
  addVertex(&mesh, x0, y0, z);
  addVertex(&mesh, x1, y0, z);
  addVertex(&mesh, x1, y1, z);
  addVertex(&mesh, x0, y1, z);
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

std::vector<uint8_t> materialBytes(Rgba baseColor, Rgba emissive) {
  std::vector<uint8_t> bytes(2 * sizeof(Rgba));
  std::memcpy(bytes.data(), &baseColor, sizeof(Rgba));
  std::memcpy(bytes.data() + sizeof(Rgba), &emissive, sizeof(Rgba));
  return bytes;
}

ShaderProgram program(const char* fragment) {
  ShaderProgram p;
  p.vertexGlslEs = kVertexShader;
  p.fragmentGlslEs = fragment;
  return p;
}

Rgba hdrAt(const FrameResult& result, uint32_t row, uint32_t column) {
  const float* p = &result.hdr[(size_t{row} * result.width + column) * 4];
  return {p[0], p[1], p[2], p[3]};
}

const uint8_t* ldrAt(const FrameResult& result, uint32_t row, uint32_t column) {
  return &result.ldr[(size_t{row} * result.width + column) * 4];
}

#define EXPECT_RGBA(actual, R, G, B, A) \
  do {                                  \
    const Rgba v = (actual);            \
    EXPECT_EQ(v.r, R);                  \
    EXPECT_EQ(v.g, G);                  \
    EXPECT_EQ(v.b, B);                  \
    EXPECT_EQ(v.a, A);                  \
  } while (0)

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << part << "\" not found in:\n" << text;
}

::testing::AssertionResult noValidationErrors(const RenderBackend& backend) {
  if (backend.validationErrors().empty()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure() << "validation errors:";
  for (const std::string& message : backend.validationErrors()) failure << "\n  " << message;
  return failure;
}

std::unique_ptr<RenderBackend> makeBackend() {
  std::string error;
  std::unique_ptr<RenderBackend> backend = createGlBackend(&error);
  EXPECT_NE(backend, nullptr) << "OSMesa GL backend unavailable: " << error;
  return backend;
}

TEST(GlBackend, ClearColourReachesHdrAndLdrTargets) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  // Values are exact in fp16; 8.0 checks the target is float, not clamped to 1.
  const float levels[] = {0.0f, 0.125f, 0.5f, 2.0f, 8.0f};
  int previousLdr = -1;
  for (float level : levels) {
    FrameDesc frame = makeFrame(16, 8);
    frame.clearColor[0] = level;
    frame.clearColor[1] = level * 0.5f;
    frame.clearColor[2] = level * 0.25f;
    frame.clearColor[3] = 1.0f;
    FrameResult result;
    std::string error;
    ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
    ASSERT_EQ(result.width, 16u);
    ASSERT_EQ(result.height, 8u);
    ASSERT_EQ(result.hdr.size(), 16u * 8u * 4u);
    ASSERT_EQ(result.ldr.size(), 16u * 8u * 4u);

    for (uint32_t row = 0; row < 8; ++row) {
      for (uint32_t column = 0; column < 16; ++column) {
        EXPECT_RGBA(hdrAt(result, row, column), level, level * 0.5f, level * 0.25f, 1.0f);
        EXPECT_EQ(std::memcmp(ldrAt(result, row, column), ldrAt(result, 0, 0), 4), 0)
            << "LDR pixel (" << row << ", " << column << ") differs from pixel (0, 0)";
      }
    }
    const int ldrRed = ldrAt(result, 0, 0)[0];
    EXPECT_GE(ldrRed, previousLdr) << "LDR red decreased as the clear value rose to " << level;
    EXPECT_EQ(ldrAt(result, 0, 0)[3], 255);
    previousLdr = ldrRed;
  }
  EXPECT_GT(previousLdr, 0);
}

// A shadow pass the backend cannot draw (shadowPassError) is refused before anything is drawn;
// an empty one (no casters) clears the atlas and draws the frame.
TEST(GlBackend, AMalformedShadowPassIsRefused) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  FrameDesc frame = makeFrame(8, 8);
  frame.shadow = ShadowPassDesc{};
  frame.shadow->atlasSize = 256;
  frame.shadow->cascades.resize(1);
  ShadowCascadeDesc& cascade = frame.shadow->cascades[0];
  cascade.viewport[2] = 256;
  cascade.viewport[3] = 256;
  FrameResult result;
  std::string error;
  EXPECT_TRUE(backend->render(frame, &result, &error)) << error;
  cascade.casters = {0};
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error, "GL backend: shadow cascade 0: caster 0 is out of range (0 casters)");
  cascade.casters.clear();
  cascade.viewport[1] = 1;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error, "GL backend: shadow cascade 0: viewport is outside the 256 texel atlas");
  cascade.viewport[1] = 0;
  frame.shadow->atlasSize = 0;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_EQ(error.rfind("GL backend: shadow atlas size 0 is outside 1..", 0), 0u) << error;
  frame.shadow.reset();
  EXPECT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_TRUE(noValidationErrors(*backend));
}

TEST(GlBackend, TriangleCoversExpectedPixelsUpright) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  // Clip-space triangle in the upper-left quadrant: corners top-left, mid-left, top-mid.
  const Mesh mesh = triangle(-1.0f, 1.0f, -1.0f, 0.0f, 0.0f, 1.0f);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  FrameDesc frame = makeFrame(64, 48);
  frame.draws.push_back(makeDraw(mesh, shaders));
  frame.draws.back().materialParams = materialBytes({1, 0, 0, 1}, {0, 0, 0, 0});
  FrameResult result;
  std::string error;
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;

  // Row 0 is the top of the image.
  EXPECT_RGBA(hdrAt(result, 1, 1), 1.0f, 0.0f, 0.0f, 1.0f);    // top-left: inside
  EXPECT_RGBA(hdrAt(result, 1, 62), 0.0f, 0.0f, 0.0f, 1.0f);   // top-right: clear
  EXPECT_RGBA(hdrAt(result, 46, 1), 0.0f, 0.0f, 0.0f, 1.0f);   // bottom-left: clear
  EXPECT_RGBA(hdrAt(result, 46, 62), 0.0f, 0.0f, 0.0f, 1.0f);  // bottom-right: clear
  EXPECT_RGBA(hdrAt(result, 20, 20), 0.0f, 0.0f, 0.0f, 1.0f);  // past the hypotenuse: clear
  EXPECT_RGBA(hdrAt(result, 5, 5), 1.0f, 0.0f, 0.0f, 1.0f);    // well inside

  // The post pass sees the same image, the same way up.
  EXPECT_GT(ldrAt(result, 1, 1)[0], 0);
  EXPECT_EQ(ldrAt(result, 1, 1)[1], 0);
  EXPECT_EQ(ldrAt(result, 46, 62)[0], 0);
}

TEST(GlBackend, MaterialParamsReachFragmentShader) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  FrameDesc frame = makeFrame(8, 8);
  frame.draws.push_back(makeDraw(mesh, shaders));
  // Both vec4s of the block: the second one checks the std140 offset (16 bytes).
  frame.draws.back().materialParams = materialBytes({0.25f, 0, 0.5f, 0.5f}, {0, 0.75f, 0.25f, 0.5f});
  FrameResult result;
  std::string error;
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_RGBA(hdrAt(result, 4, 4), 0.25f, 0.75f, 0.75f, 1.0f);
}

// A linked program is kept while draws ask for it and deleted after kEvictAfterFrames frames
// without one: a new ShaderProgram for each frame holds a bounded number of programs, one drawn
// every frame is linked once, and a program drawn again after it went is linked again and draws
// as before.
TEST(GlBackend, ProgramsNoLongerDrawnAreReleased) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  const Mesh left = quad(-1, -1, -0.5f, 1, 0);
  const Mesh right = quad(0.5f, -1, 1, 1, 0);
  const ShaderProgram steady = program(kMaterialFragmentShader);
  // Kept alive, so each frame's program has an address of its own.
  std::vector<std::unique_ptr<ShaderProgram>> programs;
  const auto frameWith = [&](const ShaderProgram& changing) {
    FrameDesc frame = makeFrame(16, 16);
    frame.draws.push_back(makeDraw(left, steady));
    frame.draws.back().materialParams = materialBytes({1, 0, 0, 1}, {0, 0, 0, 0});
    frame.draws.push_back(makeDraw(right, changing));
    frame.draws.back().materialParams = materialBytes({0, 0, 1, 1}, {0, 0, 0, 0});
    return frame;
  };
  constexpr uint64_t kFrames = 3 * kEvictAfterFrames;
  FrameResult result;
  std::string error;
  for (uint64_t i = 0; i < kFrames; ++i) {
    programs.push_back(std::make_unique<ShaderProgram>(program(kMaterialFragmentShader)));
    ASSERT_TRUE(backend->render(frameWith(*programs.back()), &result, &error)) << error;
    EXPECT_LE(backend->resources().programs, kEvictAfterFrames + 1) << "frame " << i;
  }
  EXPECT_EQ(backend->resources().programBuilds, kFrames + 1);  // the left strip's once
  ASSERT_TRUE(backend->render(frameWith(*programs.front()), &result, &error)) << error;
  EXPECT_EQ(backend->resources().programBuilds, kFrames + 2);
  EXPECT_RGBA(hdrAt(result, 8, 0), 1.0f, 0.0f, 0.0f, 1.0f);
  EXPECT_RGBA(hdrAt(result, 8, 15), 0.0f, 0.0f, 1.0f, 1.0f);
  EXPECT_TRUE(noValidationErrors(*backend));
}

// 2,000 objects sharing one mesh: one set of mesh buffers, uploaded once across frames, every
// object where its transform puts it with its own colour; a mesh edited in place is uploaded again.
TEST(GlBackend, TwoThousandDrawsShareOneMeshBuffer) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);
  constexpr uint32_t kColumns = 50, kRows = 40;  // 2,000 cells of 2x2 pixels
  const float cellW = 2.0f / kColumns, cellH = 2.0f / kRows;
  Mesh cell = quad(0, 0, cellW, cellH, 0);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  FrameDesc frame = makeFrame(2 * kColumns, 2 * kRows);
  for (uint32_t i = 0; i < kColumns * kRows; ++i) {
    frame.draws.push_back(makeDraw(cell, shaders));
    frame.draws.back().instances = {
        translation(-1.0f + float(i % kColumns) * cellW, -1.0f + float(i / kColumns) * cellH, 0)};
    const Rgba colour = i % 3 == 0 ? Rgba{0, 1, 0, 1} : Rgba{1, 0, 0, 1};
    frame.draws.back().materialParams = materialBytes(colour, {0, 0, 0, 0});
  }
  FrameResult result;
  std::string error;
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_EQ(backend->resources().meshBuffers, 1u);
  EXPECT_EQ(backend->resources().meshUploads, 1u);
  for (uint32_t i = 0; i < kColumns * kRows; ++i) {
    const uint32_t row = 2 * (kRows - 1 - i / kColumns), col = 2 * (i % kColumns);
    const Rgba got = hdrAt(result, row, col);
    ASSERT_TRUE(got.r == (i % 3 == 0 ? 0.0f : 1.0f) && got.g == (i % 3 == 0 ? 1.0f : 0.0f))
        << "object " << i << " at row " << row << " col " << col;
  }
  cell.vertices[0] = -cellW;  // edited in place: same address, new bytes
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_EQ(backend->resources().meshBuffers, 1u);
  EXPECT_EQ(backend->resources().meshUploads, 2u);
  EXPECT_TRUE(noValidationErrors(*backend));
}

// The app's own OpenGL ES context: a backend that owns an EGL context stands in for the app (its
// context is current after it renders); a second backend adopts that context through the app's
// eglGetProcAddress (no OSMesa involved), renders the same frame to the same pixels, refuses to
// render when another context is current, and leaves the context alive when destroyed.
TEST(GlBackend, RendersOnTheAppsCurrentContext) {
  std::string error;
  GlOptions appOptions;
  appOptions.context = GlContextKind::EglGles;
  auto app = createGlBackend(appOptions, &error);
  ASSERT_NE(app, nullptr) << "EGL GLES (libegl-mesa0, scripts/setup-deps.sh): " << error;
  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  FrameDesc frame = makeFrame(8, 8);
  frame.draws.push_back(makeDraw(mesh, shaders));
  frame.draws.back().materialParams = materialBytes({0.25f, 0, 0.5f, 1}, {0, 0.75f, 0, 0});
  FrameResult own, adopted;
  ASSERT_TRUE(app->render(frame, &own, &error)) << error;  // leaves the app's context current

  GlAppContext appContext;
  appContext.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
  appContext.currentContext = eglGetCurrentContext;
  auto embedded = createGlBackend(appContext, GlOptions{}, &error);
  ASSERT_NE(embedded, nullptr) << error;
  ASSERT_TRUE(embedded->render(frame, &adopted, &error)) << error;
  EXPECT_EQ(adopted.hdr, own.hdr);
  EXPECT_EQ(adopted.ldr, own.ldr);

  // Another context current (an OSMesa backend's): refused, not drawn into the wrong context.
  auto other = createGlBackend(GlOptions{GlContextKind::OsMesa}, &error);
  ASSERT_NE(other, nullptr) << error;
  ASSERT_TRUE(other->render(frame, &own, &error)) << error;
  EXPECT_FALSE(embedded->render(frame, &adopted, &error));
  EXPECT_NE(error.find("the app's GL context is not current"), std::string::npos) << error;

  // Destroyed with the app's context current; the app's backend still renders on it.
  ASSERT_TRUE(app->render(frame, &own, &error)) << error;
  embedded.reset();
  ASSERT_TRUE(app->render(frame, &own, &error)) << error;
  EXPECT_TRUE(noValidationErrors(*app));

  // Destroyed while another context is current: its names are not deleted in that context (GL
  // names are per context: they would be the other backend's buffers and textures), which goes
  // on rendering the same pixels without a GL error.
  auto late = createGlBackend(appContext, GlOptions{}, &error);
  ASSERT_NE(late, nullptr) << error;
  ASSERT_TRUE(late->render(frame, &adopted, &error)) << error;
  FrameResult before, after;
  ASSERT_TRUE(other->render(frame, &before, &error)) << error;  // OSMesa current now
  late.reset();
  ASSERT_TRUE(other->render(frame, &after, &error)) << error;
  EXPECT_EQ(after.ldr, before.ldr);
  EXPECT_TRUE(noValidationErrors(*other));
}

// What an app gets wrong when handing over its context is an error naming it, not a crash.
TEST(GlBackend, AppContextMistakesAreErrors) {
  std::string error;
  EXPECT_EQ(createGlBackend(GlAppContext{}, GlOptions{}, &error), nullptr);
  EXPECT_NE(error.find("getProcAddress is required"), std::string::npos) << error;

  // No context current (the handle callback says so).
  GlAppContext none;
  none.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
  none.currentContext = []() -> void* { return nullptr; };
  EXPECT_EQ(createGlBackend(none, GlOptions{}, &error), nullptr);
  EXPECT_NE(error.find("no GL context is current"), std::string::npos) << error;

  // A loader that resolves nothing: every missing entry point is named.
  GlAppContext empty;
  empty.getProcAddress = [](const char*) -> void* { return nullptr; };
  EXPECT_EQ(createGlBackend(empty, GlOptions{}, &error), nullptr);
  EXPECT_NE(error.find("resolves no glActiveTexture"), std::string::npos) << error;
  EXPECT_NE(error.find("glViewport"), std::string::npos) << error;
}

TEST(GlBackend, FrameAndObjectUniformsReachShaders) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  // A quad over the lower-left quadrant, moved by the model matrix to the upper-right one.
  const Mesh mesh = quad(-1, -1, 0, 0, 0);
  const ShaderProgram shaders = program(kLightColourFragmentShader);
  FrameDesc frame = makeFrame(32, 32);
  const float light[4] = {0.5f, 1.5f, 3.0f, 1.0f};
  std::memcpy(frame.frame.lightColor, light, sizeof(light));
  frame.draws.push_back(makeDraw(mesh, shaders));  // no MaterialParams: the shader has none
  frame.draws.back().instances = {translation(1.0f, 1.0f, 0.0f)};
  FrameResult result;
  std::string error;
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_RGBA(hdrAt(result, 2, 29), 0.5f, 1.5f, 3.0f, 1.0f);  // upper-right: moved quad
  EXPECT_RGBA(hdrAt(result, 29, 2), 0.0f, 0.0f, 0.0f, 1.0f);  // lower-left: where it started
}

TEST(GlBackend, DepthTestKeepsNearestSurface) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  // GL clip z in [-w, w]: smaller z is nearer.
  const Mesh nearQuad = quad(-1, -1, 1, 1, -0.5f);
  const Mesh farQuad = quad(-1, -1, 1, 1, 0.5f);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  const std::vector<uint8_t> green = materialBytes({0, 1, 0, 1}, {0, 0, 0, 0});
  const std::vector<uint8_t> red = materialBytes({1, 0, 0, 1}, {0, 0, 0, 0});

  for (bool nearFirst : {true, false}) {
    FrameDesc frame = makeFrame(8, 8);
    DrawItem nearDraw = makeDraw(nearQuad, shaders);
    nearDraw.materialParams = green;
    DrawItem farDraw = makeDraw(farQuad, shaders);
    farDraw.materialParams = red;
    frame.draws = nearFirst ? std::vector<DrawItem>{nearDraw, farDraw} : std::vector<DrawItem>{farDraw, nearDraw};
    FrameResult result;
    std::string error;
    ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
    SCOPED_TRACE(nearFirst ? "near quad drawn first" : "far quad drawn first");
    EXPECT_RGBA(hdrAt(result, 4, 4), 0.0f, 1.0f, 0.0f, 1.0f);
  }
}

TEST(GlBackend, CompileErrorIsReportedNotFatal) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  const ShaderProgram broken = program(kBrokenFragmentShader);
  FrameDesc frame = makeFrame(8, 8);
  frame.draws.push_back(makeDraw(mesh, broken));
  FrameResult result;
  std::string error;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_TRUE(contains(error, "draw 0: fragment shader failed to compile"));
  // The info log itself, not just a status.
  EXPECT_TRUE(contains(error, "syntax error"));
  // A bad shader is the caller's error, reported once, not an API validation error.
  EXPECT_TRUE(noValidationErrors(*backend));

  // The backend stays usable.
  const ShaderProgram good = program(kMaterialFragmentShader);
  frame.draws = {makeDraw(mesh, good)};
  frame.draws.back().materialParams = materialBytes({0, 0, 1, 1}, {0, 0, 0, 0});
  error.clear();
  ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  EXPECT_RGBA(hdrAt(result, 4, 4), 0.0f, 0.0f, 1.0f, 1.0f);
}

TEST(GlBackend, ShortMaterialParamsAreRejected) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  FrameDesc frame = makeFrame(8, 8);
  frame.draws.push_back(makeDraw(mesh, shaders));
  frame.draws.back().materialParams.resize(16);  // the block needs 32 bytes
  FrameResult result;
  std::string error;
  EXPECT_FALSE(backend->render(frame, &result, &error));
  EXPECT_TRUE(contains(error, "MaterialParams block is 32 bytes but the draw supplies 16"));
  EXPECT_TRUE(noValidationErrors(*backend));
}

TEST(GlBackend, DebugOutputRecordsErrors) {
  // Guards NoDebugOutputErrors against passing because nothing is listening.
  std::string error;
  std::unique_ptr<gl::Context> context =
      gl::Context::create(gl::createHeadlessContext(GlContextKind::Auto, &error), &error);
  ASSERT_NE(context, nullptr) << error;
  ASSERT_TRUE(context->makeCurrent(&error)) << error;
  ASSERT_TRUE(context->debugOutputEnabled());

  glBindBuffer(0x1234, 0);  // not a buffer target: GL_INVALID_ENUM
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  ASSERT_EQ(context->debugErrors().size(), 1u);
  EXPECT_TRUE(contains(context->debugErrors()[0], "error"));
}

TEST(GlBackend, NoDebugOutputErrors) {
  auto backend = makeBackend();
  ASSERT_NE(backend, nullptr);

  const Mesh mesh = triangle(-1, -1, 1, -1, 0, 1);
  const ShaderProgram material = program(kMaterialFragmentShader);
  const ShaderProgram light = program(kLightColourFragmentShader);
  // Two sizes exercise target re-creation; the same mesh twice exercises the per-frame upload.
  for (uint32_t size : {16u, 32u, 16u}) {
    FrameDesc frame = makeFrame(size, size);
    frame.draws.push_back(makeDraw(mesh, material));
    frame.draws.back().materialParams = materialBytes({0.5f, 0.5f, 0.5f, 1}, {0, 0, 0, 0});
    frame.draws.push_back(makeDraw(mesh, light));
    FrameResult result;
    std::string error;
    ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
  }
  EXPECT_TRUE(noValidationErrors(*backend));
}

TEST(GlBackend, TwoBackendsKeepTheirOwnContexts) {
  auto first = makeBackend();
  auto second = makeBackend();
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);

  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  const ShaderProgram shaders = program(kMaterialFragmentShader);
  for (int i = 0; i < 2; ++i) {
    for (RenderBackend* backend : {first.get(), second.get()}) {
      FrameDesc frame = makeFrame(4, 4);
      frame.draws.push_back(makeDraw(mesh, shaders));
      frame.draws.back().materialParams = materialBytes({0.5f, 0.25f, 0, 1}, {0, 0, 0, 0});
      FrameResult result;
      std::string error;
      ASSERT_TRUE(backend->render(frame, &result, &error)) << error;
      EXPECT_RGBA(hdrAt(result, 2, 2), 0.5f, 0.25f, 0.0f, 1.0f);
    }
  }
  second.reset();  // destroying one backend must not disturb the other
  FrameDesc frame = makeFrame(4, 4);
  FrameResult result;
  std::string error;
  EXPECT_TRUE(first->render(frame, &result, &error)) << error;
  EXPECT_TRUE(noValidationErrors(*first));
}

}  // namespace
}  // namespace facet::runtime

namespace facet::runtime {
namespace {

// A mediump varying whose value differs between binary16 and binary32 storage: 1 + 2^-12 rounds
// to 1 in fp16 (11 significant bits) but not in fp32. The fragment stage reads it at highp.
constexpr const char* kMediumpVaryingVertex = R"(#version 300 es
layout(location = 0) in vec3 position;
layout(std140) uniform MaterialParams { highp vec4 small; } params;
out mediump float v_value;
void main() { v_value = 1.0 + params.small.x; gl_Position = vec4(position, 1.0); }
)";
constexpr const char* kMediumpVaryingFragment = R"(#version 300 es
precision highp float;
in mediump float v_value;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = vec4((v_value - 1.0) * 4096.0, 0.0, 0.0, 1.0); }
)";
constexpr const char* kMediumpArithmeticFragment = R"(#version 300 es
precision mediump float;
layout(std140) uniform MaterialParams { mediump vec4 small; } params;
layout(location = 0) out vec4 fragColor;
void main() {
    mediump float sum = 1.0 + params.small.x;
    fragColor = vec4((sum - 1.0) * 4096.0, 0.0, 0.0, 1.0);
}
)";

float probe(const char* vertex, const char* fragment) {
  auto backend = makeBackend();
  EXPECT_NE(backend, nullptr);
  if (!backend) return -1;
  const Mesh mesh = quad(-1, -1, 1, 1, 0);
  ShaderProgram shaders;
  shaders.vertexGlslEs = vertex;
  shaders.fragmentGlslEs = fragment;
  FrameDesc frame = makeFrame(4, 4);
  frame.draws.push_back(makeDraw(mesh, shaders));
  frame.draws.back().materialParams = materialBytes({1.0f / 4096.0f, 0, 0, 0}, {0, 0, 0, 0});
  FrameResult result;
  std::string error;
  EXPECT_TRUE(backend->render(frame, &result, &error)) << error;
  return hdrAt(result, 2, 2).r;
}

}  // namespace

// Measured facts about llvmpipe's GL that the tiers' fp16 work relies on: Mesa's GLSL ES path
// stores mediump varyings as binary16 but computes mediump arithmetic at fp32. So GL renders of
// the mobile tiers show fp16 rounding of interpolated inputs (normals!), not of arithmetic; the
// fp16 emulation build exists for the rest.
TEST(GlBackend, MediumpVaryingsAreFp16AndMediumpArithmeticIsFp32OnLlvmpipe) {
  EXPECT_EQ(probe(kMediumpVaryingVertex, kMediumpVaryingFragment), 0.0f) << "fp32 storage would give 1";
  EXPECT_EQ(probe(kVertexShader, kMediumpArithmeticFragment), 1.0f) << "fp16 arithmetic would give 0";
}

}  // namespace facet::runtime
