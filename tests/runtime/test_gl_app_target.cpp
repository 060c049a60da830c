// GlRenderer::renderToFramebuffer: the frame drawn into the app's framebuffer on the app's own
// context, nothing read back. The app here is an EGL surfaceless GLES 3.2 context owned by a
// headless backend (whose debug callback sees every GL error of the context, the embedded
// backend's included); the embedded backend adopts it through eglGetProcAddress. The frame is
// examples/app's (red_plastic, two instances, an environment texture): the app's image must equal
// render()'s readback within one 8-bit step on both render paths (where MSAA or FXAA run, render()'s
// of the frame drawn in the app's row order: appRowOrderFrame below).
#include <gtest/gtest.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "example_content.h"
#include "facet/runtime/gl_backend.h"
#include "facet/runtime/render_backend.h"
#include "facet/runtime/scene_frame.h"
#include "facet/scene/scene.h"
#include "gl_context.h"
#include "gl_objects.h"
#include "test_compile.h"
#include "test_support.h"

namespace facet::runtime {
namespace {

std::string packagePath() { return facet::test::binaryDir() + "/examples/app/red_plastic.matpkg"; }
constexpr uint32_t kWidth = example::ExampleContent::kWidth;
constexpr uint32_t kHeight = example::ExampleContent::kHeight;

GlAppContext eglApp() {
  GlAppContext app;
  app.getProcAddress = [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); };
  app.currentContext = eglGetCurrentContext;
  return app;
}

// An app framebuffer whose colour attachment 0 is a texture or a renderbuffer of `format`.
struct AppFramebuffer {
  gl::Framebuffer framebuffer;
  gl::Texture texture;
  gl::Renderbuffer renderbuffer;
  GLuint id() const { return framebuffer.id(); }
};

enum class Image { Texture, Renderbuffer };

AppFramebuffer makeAppFramebuffer(Image image, GLenum format, uint32_t width, uint32_t height) {
  AppFramebuffer target;
  target.framebuffer = gl::Framebuffer::generate();
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
  if (image == Image::Texture) {
    target.texture = gl::Texture::generate();
    glBindTexture(GL_TEXTURE_2D, target.texture.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, format, GLsizei(width), GLsizei(height));
    glBindTexture(GL_TEXTURE_2D, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.id(), 0);
  } else {
    target.renderbuffer = gl::Renderbuffer::generate();
    glBindRenderbuffer(GL_RENDERBUFFER, target.renderbuffer.id());
    glRenderbufferStorage(GL_RENDERBUFFER, format, GLsizei(width), GLsizei(height));
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, target.renderbuffer.id());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

// Rows in the other order (GL's bottom-up memory against FrameResult::ldr's top first).
std::vector<uint8_t> rowsReversed(const std::vector<uint8_t>& pixels, uint32_t width, uint32_t height) {
  std::vector<uint8_t> reversed(pixels.size());
  const size_t row = size_t{width} * 4;
  for (uint32_t y = 0; y < height; ++y) {
    std::copy_n(pixels.begin() + std::ptrdiff_t((height - 1 - y) * row), row,
                reversed.begin() + std::ptrdiff_t(y * row));
  }
  return reversed;
}

// What the app reads back itself: RGBA8, rows top first like FrameResult::ldr.
std::vector<uint8_t> readFramebuffer(GLuint framebuffer, uint32_t width, uint32_t height) {
  std::vector<uint8_t> pixels(size_t{width} * height * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return rowsReversed(pixels, width, height);
}

int maxDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
  if (a.size() != b.size()) return 256;
  int worst = 0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  return worst;
}

// The frame whose render() is the app's picture drawn in the app framebuffer's row order. render()
// draws its rows top-down like Vulkan (runtime/gl/gl_row_order.h), the app's framebuffer bottom-up
// (GL's convention), and neither a 4× sample pattern nor FXAA's edge search is symmetric in y: their
// edges differ by up to 48 steps. The frame mirrored in y, drawn top-down, is the frame drawn
// bottom-up: render()'s rows reversed are the app's picture. The mirror reverses the winding, so
// each mesh is drawn from a copy in `meshes` with its triangles' winding reversed (culling kept: with
// MSAA, back faces drawn change silhouette samples); the background's direction matrix takes the
// mirrored y (D · F).
FrameDesc appRowOrderFrame(const FrameDesc& frame, std::deque<Mesh>* meshes) {
  FrameDesc mirrored = frame;
  for (int column = 0; column < 4; ++column) mirrored.frame.viewProjection[column * 4 + 1] *= -1;
  for (DrawItem& draw : mirrored.draws) {
    Mesh& reversed = meshes->emplace_back(*draw.mesh);
    for (size_t t = 0; t + 2 < reversed.indices.size(); t += 3)
      std::swap(reversed.indices[t + 1], reversed.indices[t + 2]);
    draw.mesh = &reversed;
    if (draw.program != &backgroundProgram()) continue;
    abi::BackgroundParams params;
    std::memcpy(&params, draw.materialParams.data(), sizeof params);
    for (int row = 0; row < 4; ++row) params.clipToDirection[4 + row] *= -1;
    std::memcpy(draw.materialParams.data(), &params, sizeof params);
  }
  return mirrored;
}

::testing::AssertionResult noValidationErrors(const RenderBackend& backend) {
  if (backend.validationErrors().empty()) return ::testing::AssertionSuccess();
  auto failure = ::testing::AssertionFailure() << "GL debug output errors:";
  for (const std::string& message : backend.validationErrors()) failure << "\n  " << message;
  return failure;
}

class GlAppTargetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    GlOptions options;
    options.context = GlContextKind::EglGles;
    app_ = createGlBackend(options, &error);  // makes the app's context current
    ASSERT_NE(app_, nullptr) << "EGL GLES (libegl-mesa0, scripts/setup-deps.sh): " << error;
    // The test's own GL calls, on the app's context through the same kind of table.
    appGl_ = gl::Context::create(adoptGlContext(eglApp(), &error), &error);
    ASSERT_NE(appGl_, nullptr) << error;
    ASSERT_TRUE(content_.create(packagePath().c_str(), &error)) << error;
  }
  void TearDown() override {
    // The test's GL objects die with the test body; what remains must be clean.
    if (app_) {
      EXPECT_TRUE(noValidationErrors(*app_));
    }
  }

  // The backend the app embeds, with the test's GL table current afterwards.
  std::unique_ptr<GlRenderer> embedded(PostPath path, uint32_t msaaSamples = 1, bool fxaa = false,
                                       double renderScale = 1.0, bool bloom = false) {
    GlOptions options;
    options.postPath = path;
    options.msaaSamples = msaaSamples;
    options.fxaa = fxaa;
    options.renderScale = renderScale;
    options.post.bloom = bloom;
    options.bloom = {0.3, 5, 0.5};
    options.readBackHdr = false;  // the mobile path, as an app runs it
    std::string error;
    auto renderer = createGlBackend(eglApp(), options, &error);
    EXPECT_NE(renderer, nullptr) << error;
    if (renderer) {
      EXPECT_EQ(renderer->postPath(), effectivePostPath(path, renderScale, bloom))
          << "EGL GLES offers GL_EXT_shader_framebuffer_fetch";
    }
    EXPECT_TRUE(appGl_->makeCurrent(&error)) << error;
    return renderer;
  }

  // Frame i into `target` and through render() in the app's row order (appRowOrderFrame): the app's
  // pixels, or empty on failure.
  std::vector<uint8_t> renderBoth(GlRenderer& renderer, int i, GLuint target, std::vector<uint8_t>* readBack) {
    std::string error;
    EXPECT_TRUE(content_.animate(i, &error)) << error;
    EXPECT_TRUE(renderer.renderToFramebuffer(content_.frame, GlAppTarget{target, kWidth, kHeight}, &error)) << error;
    if (!appGl_->makeCurrent(&error)) return {};
    std::vector<uint8_t> pixels = readFramebuffer(target, kWidth, kHeight);
    FrameResult result;
    std::deque<Mesh> reversed;
    EXPECT_TRUE(renderer.render(appRowOrderFrame(content_.frame, &reversed), &result, &error)) << error;
    *readBack = rowsReversed(result.ldr, result.width, result.height);
    return pixels;
  }

  // One frame into a new app framebuffer of `image`'s kind: render()'s image (and, when
  // checkInstances, the content's instances where they belong: a full-size frame).
  void expectOneFrameIsTheReadback(GlRenderer& renderer, Image image, bool checkInstances) {
    AppFramebuffer target = makeAppFramebuffer(image, GL_RGBA8, kWidth, kHeight);
    std::vector<uint8_t> readBack;
    const std::vector<uint8_t> drawn = renderBoth(renderer, 0, target.id(), &readBack);
    EXPECT_LE(maxDifference(drawn, readBack), 1);
    if (checkInstances) {
      EXPECT_EQ(content_.checkInstances(drawn), "");
    }
    std::string error;
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
  }

  std::unique_ptr<RenderBackend> app_;
  std::unique_ptr<gl::Context> appGl_;
  example::ExampleContent content_;
};

const char* pathName(PostPath path) { return path == PostPath::Merged ? "merged" : "separate"; }

// Merged: the app's texture or renderbuffer is lent to the fetch framebuffer as colour 1;
// separate: the post pass draws into the app's framebuffer. Either way the app's image is
// render()'s, frame after frame (the second frame changes one instance), without and with MSAA.
TEST_F(GlAppTargetTest, AppFramebufferGetsTheReadbackImageOnBothPaths) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    for (const auto& [image, samples] :
         {std::pair{Image::Texture, 1u}, std::pair{Image::Renderbuffer, 1u}, std::pair{Image::Texture, 4u}}) {
      SCOPED_TRACE(std::string(pathName(path)) + (image == Image::Texture ? ", texture" : ", renderbuffer") +
                   ", MSAA " + std::to_string(samples));
      auto renderer = embedded(path, samples);
      ASSERT_NE(renderer, nullptr);
      std::string error;
      AppFramebuffer target = makeAppFramebuffer(image, GL_RGBA8, kWidth, kHeight);
      std::vector<uint8_t> first, second, readBack;
      for (int i = 0; i < 2; ++i) {
        std::vector<uint8_t>& drawn = i == 0 ? first : second;
        drawn = renderBoth(*renderer, i, target.id(), &readBack);
        EXPECT_LE(maxDifference(drawn, readBack), 1) << "frame " << i;
        EXPECT_EQ(content_.checkInstances(drawn), "") << "frame " << i;
      }
      EXPECT_GT(maxDifference(first, second), 1) << "the second frame changed the rough instance's roughness";
      ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
    }
  }
}

// FXAA: forward and post into the backend's targets, the FXAA pass into the app's framebuffer
// (a texture, a renderbuffer): render()'s image on both paths.
TEST_F(GlAppTargetTest, WithFxaaTheAppFramebufferGetsTheReadbackImage) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    for (Image image : {Image::Texture, Image::Renderbuffer}) {
      SCOPED_TRACE(std::string(pathName(path)) + (image == Image::Texture ? ", texture" : ", renderbuffer"));
      auto renderer = embedded(path, 1, true);
      ASSERT_NE(renderer, nullptr);
      EXPECT_TRUE(renderer->fxaa());
      expectOneFrameIsTheReadback(*renderer, image, true);
    }
  }
}

// A render scale: the post pass upscales into the app's framebuffer (a texture, a renderbuffer),
// render()'s image, from either requested path (both run the separate one).
TEST_F(GlAppTargetTest, WithARenderScaleTheAppFramebufferGetsTheReadbackImage) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    for (Image image : {Image::Texture, Image::Renderbuffer}) {
      SCOPED_TRACE(std::string(pathName(path)) + (image == Image::Texture ? ", texture" : ", renderbuffer"));
      auto renderer = embedded(path, 1, false, 0.5);
      ASSERT_NE(renderer, nullptr);
      expectOneFrameIsTheReadback(*renderer, image, false);
    }
  }
}

// Bloom: the chain, then the post pass into the app's framebuffer (a texture, a renderbuffer),
// render()'s image, from either requested path (both run the separate one).
TEST_F(GlAppTargetTest, WithBloomTheAppFramebufferGetsTheReadbackImage) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    for (Image image : {Image::Texture, Image::Renderbuffer}) {
      SCOPED_TRACE(std::string(pathName(path)) + (image == Image::Texture ? ", texture" : ", renderbuffer"));
      auto renderer = embedded(path, 1, false, 1.0, true);
      ASSERT_NE(renderer, nullptr);
      EXPECT_EQ(renderer->bloomLevels(), 5);
      expectOneFrameIsTheReadback(*renderer, image, false);
    }
  }
}

// The merged path lends whichever image the app attached: a cube map face, a mip level other
// than 0. Frames of that image's size (the content's camera, stretched) equal render()'s.
TEST_F(GlAppTargetTest, MergedPathLendsCubeFacesAndMipLevels) {
  auto renderer = embedded(PostPath::Merged);
  ASSERT_NE(renderer, nullptr);
  std::string error;
  constexpr uint32_t kFace = kHeight;  // 240 x 240
  gl::Texture cube = gl::Texture::generate();
  glBindTexture(GL_TEXTURE_CUBE_MAP, cube.id());
  glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA8, GLsizei(kFace), GLsizei(kFace));
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  gl::Texture mipmapped = gl::Texture::generate();
  glBindTexture(GL_TEXTURE_2D, mipmapped.id());
  glTexStorage2D(GL_TEXTURE_2D, 2, GL_RGBA8, GLsizei(kWidth), GLsizei(kHeight));
  glBindTexture(GL_TEXTURE_2D, 0);

  const struct {
    const char* name;
    GLenum target;
    GLuint texture;
    GLint level;
    uint32_t width, height;
  } images[] = {
      {"cube face -Y", GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, cube.id(), 0, kFace, kFace},
      {"2D level 1", GL_TEXTURE_2D, mipmapped.id(), 1, kWidth / 2, kHeight / 2},
  };
  for (const auto& image : images) {
    SCOPED_TRACE(image.name);
    gl::Framebuffer framebuffer = gl::Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, image.target, image.texture, image.level);
    ASSERT_TRUE(content_.animate(0, &error)) << error;
    content_.frame.width = image.width;
    content_.frame.height = image.height;
    ASSERT_TRUE(
        renderer->renderToFramebuffer(content_.frame, GlAppTarget{framebuffer.id(), image.width, image.height}, &error))
        << error;
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
    const std::vector<uint8_t> drawn = readFramebuffer(framebuffer.id(), image.width, image.height);
    FrameResult result;
    ASSERT_TRUE(renderer->render(content_.frame, &result, &error)) << error;
    EXPECT_LE(maxDifference(drawn, result.ldr), 1);
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
  }
}

// gl_backend.h's promise: the target bound for drawing and reading, the full viewport, program 0,
// vertex array 0, the fixed-function tests off; and the app's scissor, colour mask, blending and
// pixel-unpack buffer left set by its own pass do not clip, tint or feed the frame.
TEST_F(GlAppTargetTest, LeavesTheTargetBoundWithAFullViewport) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(pathName(path));
    auto renderer = embedded(path);
    ASSERT_NE(renderer, nullptr);
    std::string error;
    AppFramebuffer target = makeAppFramebuffer(Image::Texture, GL_RGBA8, kWidth, kHeight);
    AppFramebuffer other = makeAppFramebuffer(Image::Texture, GL_RGBA8, 4, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, other.id());
    glViewport(1, 2, 3, 4);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    // A streaming buffer left bound: the first frame's environment upload must not read it.
    gl::Buffer staging = gl::Buffer::generate();
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, staging.id());
    glBufferData(GL_PIXEL_UNPACK_BUFFER, 16, nullptr, GL_STREAM_DRAW);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 7);
    ASSERT_TRUE(content_.animate(0, &error)) << error;
    ASSERT_TRUE(renderer->renderToFramebuffer(content_.frame, GlAppTarget{target.id(), kWidth, kHeight}, &error))
        << error;

    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
    GLint draw = -1, read = -1, program = -1, vertexArray = -1, viewport[4] = {-1, -1, -1, -1};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray);
    EXPECT_EQ(draw, GLint(target.id()));
    EXPECT_EQ(read, GLint(target.id()));
    EXPECT_EQ(viewport[0], 0);
    EXPECT_EQ(viewport[1], 0);
    EXPECT_EQ(viewport[2], GLint(kWidth));
    EXPECT_EQ(viewport[3], GLint(kHeight));
    EXPECT_EQ(program, 0);
    EXPECT_EQ(vertexArray, 0);
    GLint unpackBuffer = -1, rowLength = -1;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    EXPECT_EQ(unpackBuffer, 0);
    EXPECT_EQ(rowLength, 0);
    for (GLenum capability : {GL_SCISSOR_TEST, GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_STENCIL_TEST}) {
      EXPECT_EQ(glIsEnabled(capability), GL_FALSE) << "capability 0x" << std::hex << capability;
    }
    const std::vector<uint8_t> drawn = readFramebuffer(target.id(), kWidth, kHeight);
    FrameResult result;
    ASSERT_TRUE(renderer->render(content_.frame, &result, &error)) << error;
    EXPECT_LE(maxDifference(drawn, result.ldr), 1);
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
  }
}

// The sun's shadow pass runs in the app's frame too (before the forward pass, into the backend's
// own atlas): a sphere's shadow on the ground, the same as render()'s on both paths, and the
// app's framebuffer left bound with no scissor or depth offset of the pass's on.
TEST_F(GlAppTargetTest, TheSunsShadowIsDrawnIntoTheAppFramebuffer) {
  compiler::BuildOptions build;
  build.shadowCascadeCounts = {0, 2};
  const std::string packages = test::writePackagesFromTexts(
      "gl-app-shadows", {"material grey { shading lit\n surface { baseColor = vec3(0.7, 0.7, 0.7) } }"}, build);
  const auto frameOf = [&](bool casts, std::unique_ptr<SceneFrame>* out) {
    const std::string json = R"({"width": )" + std::to_string(kWidth) + R"(, "height": )" + std::to_string(kHeight) +
                             R"(,
      "camera": {"position": [0, 4, 6], "target": [0, 0, 0], "fovY": 45},
      "sun": {"direction": [0.3, -1, -0.2], "illuminance": 100000, "castShadows": )" +
                             (casts ? "true" : "false") + R"(},
      "sky": {"luminance": 0},
      "shadows": {"atlasSize": 512, "cascades": 2},
      "objects": [{"mesh": "plane", "material": "grey", "scale": [20, 1, 20]},
                  {"mesh": "sphere", "material": "grey", "position": [0, 1.2, 0]}]})";
    std::string error;
    auto scene = parseScene("app-shadow.json", json, &error);
    ASSERT_TRUE(scene) << error;
    *out = SceneFrame::prepare(*scene, packages, &error);
    ASSERT_TRUE(*out) << error;
  };
  std::unique_ptr<SceneFrame> shadowed, unshadowed;
  frameOf(true, &shadowed);
  frameOf(false, &unshadowed);
  ASSERT_TRUE(shadowed && unshadowed);
  ASSERT_TRUE(shadowed->frame().shadow);
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(pathName(path));
    auto renderer = embedded(path);
    ASSERT_NE(renderer, nullptr);
    std::string error;
    AppFramebuffer target = makeAppFramebuffer(Image::Texture, GL_RGBA8, kWidth, kHeight);
    const auto drawInto = [&](const FrameDesc& frame) {
      EXPECT_TRUE(renderer->renderToFramebuffer(frame, GlAppTarget{target.id(), kWidth, kHeight}, &error)) << error;
      EXPECT_TRUE(appGl_->makeCurrent(&error)) << error;
      return readFramebuffer(target.id(), kWidth, kHeight);
    };
    const std::vector<uint8_t> lit = drawInto(unshadowed->frame());
    const std::vector<uint8_t> drawn = drawInto(shadowed->frame());
    GLint framebuffer = -1;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    EXPECT_EQ(framebuffer, GLint(target.id()));
    EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE);
    EXPECT_EQ(glIsEnabled(GL_POLYGON_OFFSET_FILL), GL_FALSE);
    // The shadow: ground pixels the sun lights without the pass and the pass darkens.
    size_t darkened = 0;
    for (size_t i = 0; i < drawn.size(); i += 4) darkened += lit[i] > 40 && drawn[i] < lit[i] / 4;
    EXPECT_GT(darkened, size_t{kWidth} * kHeight / 100) << "of " << kWidth * kHeight << " pixels";
    FrameResult result;
    ASSERT_TRUE(renderer->render(shadowed->frame(), &result, &error)) << error;
    EXPECT_LE(maxDifference(drawn, result.ldr), 1);
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
  }
}

// The default framebuffer (a window's surface; here a pbuffer) has no image to lend: a merged
// backend draws it by the separate path, still the same pixels.
TEST_F(GlAppTargetTest, DefaultFramebufferTakesTheSeparatePath) {
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLContext context = eglGetCurrentContext();
  const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                     EGL_PBUFFER_BIT,
                                     EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_ES3_BIT,
                                     EGL_RED_SIZE,
                                     8,
                                     EGL_GREEN_SIZE,
                                     8,
                                     EGL_BLUE_SIZE,
                                     8,
                                     EGL_ALPHA_SIZE,
                                     8,
                                     EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  ASSERT_TRUE(eglChooseConfig(display, configAttributes, &config, 1, &configs) && configs == 1)
      << "no RGBA8 pbuffer config on the surfaceless display";
  const EGLint surfaceAttributes[] = {EGL_WIDTH, EGLint(kWidth), EGL_HEIGHT, EGLint(kHeight), EGL_NONE};
  const EGLSurface surface = eglCreatePbufferSurface(display, config, surfaceAttributes);
  ASSERT_NE(surface, EGL_NO_SURFACE) << "eglCreatePbufferSurface: 0x" << std::hex << eglGetError();
  ASSERT_TRUE(eglMakeCurrent(display, surface, surface, context));

  auto renderer = embedded(PostPath::Merged);
  ASSERT_NE(renderer, nullptr);
  std::vector<uint8_t> readBack;
  const std::vector<uint8_t> drawn = renderBoth(*renderer, 0, 0, &readBack);
  EXPECT_LE(maxDifference(drawn, readBack), 1);
  EXPECT_EQ(content_.checkInstances(drawn), "");

  renderer.reset();
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
  eglDestroySurface(display, surface);
}

// A target the post pass cannot write is an error naming why, with nothing drawn and no GL error
// raised in the app's context; the next frame into a good target renders.
TEST_F(GlAppTargetTest, UnusableTargetsAreErrors) {
  for (PostPath path : {PostPath::Merged, PostPath::Separate}) {
    SCOPED_TRACE(pathName(path));
    auto renderer = embedded(path);
    ASSERT_NE(renderer, nullptr);
    std::string error;
    AppFramebuffer good = makeAppFramebuffer(Image::Texture, GL_RGBA8, kWidth, kHeight);
    AppFramebuffer srgb = makeAppFramebuffer(Image::Texture, GL_SRGB8_ALPHA8, kWidth, kHeight);
    AppFramebuffer integer = makeAppFramebuffer(Image::Texture, GL_RGBA8UI, kWidth, kHeight);
    gl::Framebuffer empty = gl::Framebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, empty.id());  // now an object, with no attachment
    AppFramebuffer noDrawBuffer = makeAppFramebuffer(Image::Texture, GL_RGBA8, kWidth, kHeight);
    glBindFramebuffer(GL_FRAMEBUFFER, noDrawBuffer.id());
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ASSERT_TRUE(content_.animate(0, &error)) << error;

    const struct {
      GlAppTarget target;
      const char* message;
    } cases[] = {
        {{good.id(), 0, 0}, "the app's target has size 0x0"},
        {{good.id(), kWidth / 2, kHeight}, "but the frame is 480x240"},
        {{0, kWidth, kHeight}, "the default framebuffer is not complete: undefined"},  // surfaceless
        {{9999, kWidth, kHeight}, "framebuffer 9999 is not a framebuffer object"},
        {{empty.id(), kWidth, kHeight}, "missing attachment"},
        {{srgb.id(), kWidth, kHeight}, "sRGB-encoded"},
        {{integer.id(), kWidth, kHeight}, "not unsigned-normalised"},
        {{noDrawBuffer.id(), kWidth, kHeight}, "draw buffer 0 set to GL_NONE"},
    };
    for (const auto& wrong : cases) {
      error.clear();
      EXPECT_FALSE(renderer->renderToFramebuffer(content_.frame, wrong.target, &error)) << wrong.message;
      EXPECT_NE(error.find(wrong.message), std::string::npos) << error;
      EXPECT_TRUE(noValidationErrors(*app_)) << wrong.message;
    }
    EXPECT_TRUE(renderer->renderToFramebuffer(content_.frame, GlAppTarget{good.id(), kWidth, kHeight}, &error))
        << error;
    ASSERT_TRUE(appGl_->makeCurrent(&error)) << error;
    EXPECT_EQ(content_.checkInstances(readFramebuffer(good.id(), kWidth, kHeight)), "");
  }
}

}  // namespace
}  // namespace facet::runtime
