// Colour grading on the CPU: the LUT built from settings (identity when neutral, each setting
// doing what it says), .cube files read as Adobe/Resolve write them and hostile ones refused
// with file:line diagnostics, and the scene's "post" settings (grading, vignette) with the .cube
// file confined to the asset root.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "facet/runtime/color_grading.h"
#include "facet/runtime/scene_frame.h"
#include "facet/runtime/vignette.h"
#include "facet/scene/scene.h"
#include "test_support.h"

namespace {

using namespace facet::runtime;

std::array<float, 3> at(const ColorLut& lut, float r, float g, float b) { return sampleColorLut(lut, {r, g, b}); }

// A .cube of size n whose entry (r, g, b) is f(r, g, b) of the lattice point.
template <typename F>
std::string cubeText(uint32_t n, F f, const std::string& header = "") {
  std::string text = header + "LUT_3D_SIZE " + std::to_string(n) + "\n";
  for (uint32_t b = 0; b < n; ++b)
    for (uint32_t g = 0; g < n; ++g)
      for (uint32_t r = 0; r < n; ++r) {
        const std::array<double, 3> v = f(r / double(n - 1), g / double(n - 1), b / double(n - 1));
        text += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
      }
  return text;
}

std::string cubeError(const std::string& text) {
  std::string error;
  EXPECT_FALSE(parseCubeLut("lut.cube", text, &error)) << text.substr(0, 200);
  return error;
}

}  // namespace

TEST(ColorGrading, NeutralSettingsGiveTheIdentityTable) {
  const ColorLut lut = buildColorLut({});
  ASSERT_EQ(lut.size, 32u);
  ASSERT_EQ(lut.rgb.size(), 32u * 32 * 32 * 3);
  double worst = 0;
  for (uint32_t i = 0; i < lut.rgb.size(); ++i) {
    const uint32_t entry = i / 3, channel = i % 3;
    const uint32_t coordinate = channel == 0 ? entry % 32 : channel == 1 ? entry / 32 % 32 : entry / 1024;
    worst = std::max(worst, std::abs(double(lut.rgb[i]) - coordinate / 31.0));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(ColorGrading, EachSettingDoesWhatItSays) {
  ColorGradingSettings warm;
  warm.temperature = 0.5;
  const auto w = at(buildColorLut(warm), 0.5f, 0.5f, 0.5f);
  EXPECT_GT(w[0], w[2] + 0.02f) << "a warmer white balance turns grey orange";
  ColorGradingSettings cool;
  cool.temperature = -0.5;
  const auto c = at(buildColorLut(cool), 0.5f, 0.5f, 0.5f);
  EXPECT_GT(c[2], c[0] + 0.02f);
  ColorGradingSettings magenta;
  magenta.tint = 0.5;
  const auto m = at(buildColorLut(magenta), 0.5f, 0.5f, 0.5f);
  EXPECT_LT(m[1], m[0] - 0.01f);
  EXPECT_LT(m[1], m[2] - 0.01f);

  ColorGradingSettings grey;
  grey.saturation = 0;
  const auto g = at(buildColorLut(grey), 0.9f, 0.2f, 0.4f);
  EXPECT_NEAR(g[0], g[1], 1e-3);
  EXPECT_NEAR(g[1], g[2], 1e-3);

  // Contrast pivots on middle grey (0.18 linear, 0.4614 encoded): darker below, lighter above.
  ColorGradingSettings contrast;
  contrast.contrast = 1.5;
  const ColorLut k = buildColorLut(contrast, 64);
  const float middle = 0.46135613f;
  EXPECT_NEAR(at(k, middle, middle, middle)[0], middle, 2e-3);
  EXPECT_LT(at(k, 0.2f, 0.2f, 0.2f)[0], 0.2f - 0.03f);
  EXPECT_GT(at(k, 0.7f, 0.7f, 0.7f)[0], 0.7f + 0.03f);

  ColorGradingSettings gain;
  gain.gain = {0.5, 1, 1};
  const auto h = at(buildColorLut(gain), 1.0f, 1.0f, 1.0f);
  EXPECT_NEAR(h[0], 0.7353569f, 1e-4) << "half the linear red: sRGB(0.5)";
  EXPECT_NEAR(h[1], 1.0f, 1e-6);
}

TEST(ColorGrading, ParsesTitleCommentsAndDomainAsAdobeAndResolveWriteThem) {
  std::string error;
  const std::string text =
      "# written by a grading tool\r\nTITLE \"warm fade\"\r\n\r\nDOMAIN_MIN 0 0 0\r\nDOMAIN_MAX 2 2 2\r\n" +
      cubeText(2, [](double r, double g, double b) {
        return std::array<double, 3>{r, g, b};
      });
  const auto lut = parseCubeLut("warm.cube", text, &error);
  ASSERT_TRUE(lut) << error;
  EXPECT_EQ(lut->title, "warm fade");
  EXPECT_EQ(lut->size, 2u);
  // Input 0.5 is a quarter of the domain [0, 2]: the identity table returns 0.25 there.
  EXPECT_NEAR(at(*lut, 0.5f, 1.0f, 2.0f)[0], 0.25f, 1e-6);
  EXPECT_NEAR(at(*lut, 0.5f, 1.0f, 2.0f)[1], 0.5f, 1e-6);
  EXPECT_NEAR(at(*lut, 0.5f, 1.0f, 2.0f)[2], 1.0f, 1e-6);
  const auto resolve = parseCubeLut("r.cube",
                                    "LUT_3D_INPUT_RANGE 0 1\n" + cubeText(3,
                                                                          [](double r, double g, double b) {
                                                                            return std::array<double, 3>{b, g, r};
                                                                          }),
                                    &error);
  ASSERT_TRUE(resolve) << error;
  // Resampled to the GPU's 32 points, a table of another size keeps what it interpolates to.
  const ColorLut sized = resampleColorLut(*resolve, 32);
  ASSERT_EQ(sized.size, 32u);
  const auto swapped = at(sized, 0.3f, 0.6f, 0.9f);
  EXPECT_NEAR(swapped[0], 0.9f, 1e-5);
  EXPECT_NEAR(swapped[2], 0.3f, 1e-5);
  const ColorLutTexels texels = colorLutTexels(*resolve);
  EXPECT_EQ(texels.rgba.size(), 32u * 32 * 32 * 4);
}

// What editors and tools write around the table reads as the same table: a UTF-8 byte-order mark,
// LF, CR LF or lone-CR line ends, and numbers too small for a double (0 in the half-float table).
TEST(ColorGrading, ByteOrderMarkLineEndsAndUnderflowReadAsTheSameTable) {
  const auto identity = [](double r, double g, double b) { return std::array<double, 3>{r, g, b}; };
  std::string error;
  const auto plain = parseCubeLut("lf.cube", cubeText(2, identity), &error);
  ASSERT_TRUE(plain) << error;
  std::string crOnly = cubeText(2, identity), crlf;
  for (char& c : crOnly)
    if (c == '\n') c = '\r';
  for (char c : cubeText(2, identity)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::string tiny = cubeText(2, identity);
  tiny.replace(tiny.find("0.000000 0.000000 0.000000"), 8, "1e-400  ");
  for (const std::string& text : {"\xEF\xBB\xBF" + cubeText(2, identity), crOnly, crlf, tiny}) {
    const auto lut = parseCubeLut("edited.cube", text, &error);
    ASSERT_TRUE(lut) << error;
    EXPECT_EQ(lut->size, 2u);
    EXPECT_EQ(lut->rgb, plain->rgb);
  }
}

TEST(ColorGrading, HostileCubeFilesAreDiagnosedWithFileAndLine) {
  const auto identity = [](double r, double g, double b) { return std::array<double, 3>{r, g, b}; };
  EXPECT_EQ(cubeError("LUT_3D_SIZE 1\n0 0 0\n"), "lut.cube:1: error: LUT_3D_SIZE 1 is outside 2..64");
  EXPECT_EQ(cubeError("# big\nLUT_3D_SIZE 65\n"), "lut.cube:2: error: LUT_3D_SIZE 65 is outside 2..64");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2.5\n"), "lut.cube:1: error: LUT_3D_SIZE takes a whole number in digits, not '2.5'");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2.00000001\n"),
            "lut.cube:1: error: LUT_3D_SIZE takes a whole number in digits, not '2.00000001'");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2.0\n"), "lut.cube:1: error: LUT_3D_SIZE takes a whole number in digits, not '2.0'");
  EXPECT_EQ(cubeError("LUT_3D_SIZE -3\n"), "lut.cube:1: error: LUT_3D_SIZE -3 is outside 2..64");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 99999999999\n"), "lut.cube:1: error: LUT_3D_SIZE 99999999999 is outside 2..64");
  EXPECT_EQ(cubeError("LUT_3D_SIZE many\n"), "lut.cube:1: error: expected a number, not 'many'");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\n0 0 0\n1 0 0\n"),
            "lut.cube:3: error: the table ends after 2 of the 8 entries LUT_3D_SIZE 2 gives");
  std::string nan = cubeText(2, identity);
  nan.replace(nan.find("1.000000 1.000000 1.000000"), 8, "nan     ");
  EXPECT_EQ(cubeError(nan), "lut.cube:9: error: 'nan' is not a finite number");
  EXPECT_EQ(cubeError(cubeText(2, identity) + "0 0 0\n"),
            "lut.cube:10: error: more than the 8 entries LUT_3D_SIZE 2 gives");
  EXPECT_EQ(cubeError("0 0 0\n"), "lut.cube:1: error: a table entry before LUT_3D_SIZE");
  EXPECT_EQ(cubeError("LUT_1D_SIZE 1024\n"), "lut.cube:1: error: a 1D LUT (LUT_1D_SIZE): only 3D tables are supported");
  EXPECT_EQ(cubeError("LUT_3D_SIZEE 2\n"), "lut.cube:1: error: unknown keyword 'LUT_3D_SIZEE'");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\n0 0 0\nTITLE \"late\"\n"),
            "lut.cube:3: error: 'TITLE' after the table's first entry");
  EXPECT_EQ(cubeError("DOMAIN_MIN 1 0 0\nDOMAIN_MAX 1 1 1\n"),
            "lut.cube:2: error: DOMAIN_MIN must be below DOMAIN_MAX in every channel");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\n0 0\n"), "lut.cube:2: error: a table entry takes three numbers");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\n0 1e9 0\n"),
            "lut.cube:2: error: '1e9' is beyond the half-float range (65504) the table is stored in");
  EXPECT_EQ(cubeError(std::string("LUT_3D_SIZE 2\n0 0\0 0\n", 21)), "lut.cube:2: error: a NUL byte: not a text file");
  EXPECT_EQ(cubeError(""), "lut.cube:1: error: an empty file: not a 3D .cube file");
  EXPECT_EQ(cubeError("\xEF\xBB\xBF\r\n"), "lut.cube:1: error: an empty file: not a 3D .cube file");
  EXPECT_EQ(cubeError("# only a comment\n"), "lut.cube:1: error: no LUT_3D_SIZE: not a 3D .cube file");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\n0 1e400 0\n"),
            "lut.cube:2: error: '1e400' is beyond the half-float range (65504) the table is stored in");
  // With lone CRs as line ends, a mistake is still found at its own line.
  EXPECT_EQ(cubeError("# old Mac tool\rLUT_3D_SIZE 2\r0 0\r"), "lut.cube:3: error: a table entry takes three numbers");
  EXPECT_EQ(cubeError("TITLE untitled\n"), "lut.cube:1: error: TITLE takes a quoted string");
  EXPECT_EQ(cubeError("LUT_3D_SIZE 2\nLUT_3D_SIZE 2\n"), "lut.cube:2: error: a second LUT_3D_SIZE");

  // Files: not there, or larger than any table of size 64 needs (refused before reading).
  const std::string dir = facet::test::scratchDir("color-grading-files");
  std::string error;
  EXPECT_FALSE(loadCubeLut(dir + "/missing.cube", &error));
  EXPECT_NE(error.find("missing.cube: error: not a regular file"), std::string::npos) << error;
  const std::string huge = dir + "/huge.cube";
  { std::ofstream(huge) << "LUT_3D_SIZE 2\n"; }
  std::filesystem::resize_file(huge, kMaxCubeFileBytes + 1);
  EXPECT_FALSE(loadCubeLut(huge, &error));
  EXPECT_NE(error.find("huge.cube: error: larger than the 16777216 bytes"), std::string::npos) << error;
}

TEST(ColorGrading, SceneNamesGradingAndVignetteAndItsCubeFileStaysUnderTheAssetRoot) {
  const std::string dir = facet::test::scratchDir("color-grading-scene");
  {
    std::ofstream(dir + "/swap.cube") << cubeText(2, [](double r, double g, double b) {
      return std::array<double, 3>{b, g, r};
    });
  }
  std::string error;
  auto scene = parseScene(dir + "/s.json", R"({"post": {"toneCurve": "neutral",
      "grading": {"temperature": 0.2, "tint": -0.1, "contrast": 1.2, "saturation": 0.8, "lift": [0, 0, 0.02], "gamma": [1, 1, 1.1], "gain": [1, 0.9, 1]},
      "vignette": {"intensity": 0.4, "radius": 0.5, "smoothness": 1, "roundness": 0.5}}, "objects": []})",
                          &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_TRUE(scene->post.colorGrading);
  EXPECT_TRUE(scene->post.vignette);
  EXPECT_FALSE(scene->post.dither);
  EXPECT_EQ(scene->grading.temperature, 0.2);
  EXPECT_EQ(scene->grading.gain[1], 0.9);
  EXPECT_EQ(scene->vignette.roundness, 0.5);
  EXPECT_TRUE(scene->gradingLut.empty());

  scene = parseScene(dir + "/s.json", R"({"post": {"grading": {"lut": "swap.cube"}}, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_EQ(std::filesystem::path(scene->gradingLut).filename(), "swap.cube");
  // The frame carries the table the scene names, resampled to the GPU's size.
  auto frame = SceneFrame::prepare(*scene, dir, &error);
  ASSERT_TRUE(frame) << error;
  ASSERT_TRUE(frame->frame().colorLut);
  EXPECT_EQ(frame->frame().colorLut->rgba.size(), 32u * 32 * 32 * 4);
  { std::ofstream(dir + "/bad.cube") << "LUT_3D_SIZE 2\n0 0 0\n"; }
  scene = parseScene(dir + "/s.json", R"({"post": {"grading": {"lut": "bad.cube"}}, "objects": []})", &error);
  ASSERT_TRUE(scene) << error;
  EXPECT_FALSE(SceneFrame::prepare(*scene, dir, &error));
  EXPECT_NE(error.find("bad.cube:2: error: the table ends after 1 of the 8 entries"), std::string::npos) << error;

  EXPECT_FALSE(
      parseScene(dir + "/s.json", R"({"post": {"grading": {"lut": "../outside.cube"}}, "objects": []})", &error));
  EXPECT_NE(error.find("/post/grading/lut: '../outside.cube' is outside the folder this scene may read files from"),
            std::string::npos)
      << error;
  EXPECT_FALSE(parseScene(dir + "/s.json",
                          R"({"post": {"grading": {"lut": "swap.cube", "contrast": 2}}, "objects": []})", &error));
  EXPECT_NE(error.find("/post/grading/lut: give either a .cube file or grading settings, not both"), std::string::npos)
      << error;
  EXPECT_FALSE(parseScene(dir + "/s.json", R"({"post": {"grading": {"temperature": 2}}, "objects": []})", &error));
  EXPECT_NE(error.find("/post/grading/temperature: value 2 is outside [-1.0, 1.0]"), std::string::npos) << error;
  EXPECT_FALSE(parseScene(dir + "/s.json", R"({"post": {"vignette": {"intensity": 0.5, "radious": 1}}, "objects": []})",
                          &error));
  EXPECT_NE(error.find("/post/vignette/radious: unknown key 'radious'"), std::string::npos) << error;
}

TEST(ColorGrading, VignetteUniformsCarryTheFrameSize) {
  const facet::abi::PostUniforms u = postUniforms({0.5, 0.8, 0.3, 1}, 200, 100);
  EXPECT_EQ(u.vignette[0], 0.5f);
  EXPECT_EQ(u.vignette[2], 0.3f);
  EXPECT_EQ(u.viewport[0], 1.0f / 200);
  EXPECT_EQ(u.viewport[1], 1.0f / 100);
  EXPECT_EQ(u.viewport[2], 2.0f);
}
