// facet-texture: `matc texture` (docs/texture-format.md) as a program of its own, so that matc
// links neither astcenc nor the runtime's image decoding. matc runs it as "<matc> texture"
// (matc/run_helper_program.cpp): its usage and messages then read as matc's.
//
// A PNG becomes a KTX2 file: the mip chain made exactly as the runtime makes it for a PNG
// (runtime::decodeImageTexture: 2x2 box filter, sRGB colour averaged in linear light), then each
// level encoded to ASTC by astcenc on one thread (the same bytes on every run).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "facet/cli/command_line.h"
#include "facet/cli/inputs.h"
#include "facet/cli/outputs.h"
#include "facet/package/atomic_file.h"
#include "facet/runtime/image_texture.h"
#include "facet/texture/astc.h"
#include "facet/texture/ktx2.h"

namespace {

using facet::texture::TextureUsage;

// The block size each usage gets unless --block says otherwise: the largest block whose PSNR on
// the example textures stays above the floor docs/texture-format.md gives (measured there).
constexpr const char* kDefaultBlock[] = {"6x6", "5x5", "6x6"};  // color, normal, data

const std::map<std::string, float> kQualityNames = {
    {"fastest", 0.0f}, {"fast", 10.0f}, {"medium", 60.0f}, {"thorough", 98.0f}, {"exhaustive", 100.0f}};

// PSNR in dB of `decoded` against `source` over RGB (and alpha unless it is ignored), 8-bit values.
double psnr(const std::vector<uint8_t>& source, const std::vector<uint8_t>& decoded, bool withAlpha) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < source.size(); ++i) {
    if (!withAlpha && i % 4 == 3) continue;
    const double d = double(source[i]) - double(decoded[i]);
    sum += d * d;
    ++count;
  }
  if (sum == 0) return INFINITY;
  return 10.0 * std::log10(255.0 * 255.0 / (sum / double(count)));
}

}  // namespace

int main(int argc, char** argv) {
  facet::removeTemporaryFilesOnSignals();
  facet::cli::setProgramName(std::string_view(argv[0]).ends_with(" texture") ? "matc" : "facet-texture");
  CLI::App app{"encode a PNG into an ASTC KTX2 texture with its mip levels (docs/texture-format.md)"};
  std::string input, output, usageName, block, quality = "medium", format = "astc";
  app.add_option("input", input, "PNG image")->required();
  app.add_option("-o,--output", output, "KTX2 file to write")->required();
  app.add_option("--usage", usageName,
                 "color (sRGB colour, texture(srgb)) | normal (tangent-space normal map, texture(normal)) | data "
                 "(linear values, texture(linear))")
      ->required()
      ->check(CLI::IsMember({"color", "normal", "data"}));
  app.add_option("--block", block, "ASTC block size: 4x4 | 5x5 | 6x6 | 8x8 (default: color 6x6, normal 5x5, data 6x6)")
      ->check(CLI::IsMember({"4x4", "5x5", "6x6", "8x8"}));
  app.add_option("--quality", quality, "astcenc effort: fastest | fast | medium | thorough | exhaustive")
      ->check(CLI::IsMember({"fastest", "fast", "medium", "thorough", "exhaustive"}));
  app.add_option("--format", format, "astc | rgba8 (uncompressed, for comparison)")
      ->check(CLI::IsMember({"astc", "rgba8"}));
  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;

  const TextureUsage usage = usageName == "color"    ? TextureUsage::Color
                             : usageName == "normal" ? TextureUsage::Normal
                                                     : TextureUsage::Data;
  if (block.empty()) block = kDefaultBlock[int(usage)];
  const bool srgb = usage == TextureUsage::Color;
  if (!facet::cli::outputsSpareInputs({{"the input image", input}}, {{"-o", output}})) return 1;

  std::string error;
  std::optional<facet::runtime::Texture> source = facet::runtime::loadImageTexture(input, srgb, &error);
  if (!source) {
    facet::cli::printError(error);
    return 1;
  }
  facet::texture::Ktx2Image image;
  image.width = source->width;
  image.height = source->height;
  facet::texture::AstcSettings settings;
  settings.usage = usage;
  settings.blockWidth = settings.blockHeight = uint32_t(block[0] - '0');
  settings.quality = kQualityNames.at(quality);
  const auto started = std::chrono::steady_clock::now();
  double levelZeroPsnr = INFINITY;
  if (format == "rgba8") {
    image.vkFormat = srgb ? 43 : 37;
    image.levels = source->levels;
  } else {
    image.vkFormat = facet::texture::findAstcFormat(settings.blockWidth, settings.blockHeight, srgb)->vkFormat;
    for (size_t i = 0; i < source->levels.size(); ++i) {
      const uint32_t w = std::max(1u, image.width >> i), h = std::max(1u, image.height >> i);
      auto blocks = facet::texture::encodeAstc(source->levels[i], w, h, settings, &error);
      std::optional<std::vector<uint8_t>> decoded;
      if (blocks && i == 0)
        decoded = facet::texture::decodeAstc(*blocks, w, h, settings.blockWidth, settings.blockHeight, srgb, &error);
      if (!blocks || (i == 0 && !decoded)) {
        facet::cli::printError(input + ": level " + std::to_string(i) + ": " + error);
        return 1;
      }
      if (i == 0) levelZeroPsnr = psnr(source->levels[0], *decoded, usage != TextureUsage::Normal);
      image.levels.push_back(std::move(*blocks));
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::vector<uint8_t> bytes = facet::texture::writeKtx2(image, &error);
  if (bytes.empty()) {
    facet::cli::printError(input + ": " + error);
    return 1;
  }
  uint64_t rgbaBytes = 0, levelBytes = 0;
  for (const auto& level : source->levels) rgbaBytes += level.size();
  for (const auto& level : image.levels) levelBytes += level.size();
  if (!facet::cli::writeOutputs({""}, {{output, std::move(bytes)}})) return 1;
  std::printf(
      "%s: %ux%u, %zu levels, %s, %llu bytes of levels (RGBA8: %llu, %.1f%%), level 0 PSNR %.2f dB, "
      "encoded in %.3f s\n",
      output.c_str(), image.width, image.height, image.levels.size(),
      facet::texture::findKtx2Format(image.vkFormat)->name, static_cast<unsigned long long>(levelBytes),
      static_cast<unsigned long long>(rgbaBytes), 100.0 * double(levelBytes) / double(rgbaBytes), levelZeroPsnr,
      seconds);
  return 0;
}
