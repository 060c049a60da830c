// facet-view: renders a scene JSON headless to PNG with the Vulkan and/or GL backend.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "facet/atomic_file.h"
#include "facet/render_backend.h"
#include "facet/runtime/png.h"
#include "facet/runtime/scene_frame.h"

namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "facet-view: error: %s\n", message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  facet::removeTemporaryFilesOnSignals();  // an interrupted PNG write leaves nothing behind
  CLI::App app{"facet-view: renders a Facet scene headless to PNG"};
  std::string scenePath, packageDir = ".", outDir = ".", backendName = "both", tier;
  bool validation = false;
  app.add_option("scene", scenePath, "scene JSON")->required();
  app.add_option("--packages", packageDir, "folder holding <material>.matpkg files");
  app.add_option("--out", outDir, "folder for the PNG files");
  app.add_option("--backend", backendName, "vulkan | gl | both")->check(CLI::IsMember({"vulkan", "gl", "both"}));
  app.add_option("--tier", tier, "render at this tier instead of the scene's (reference, high, mid, low)");
  app.add_flag("--validation", validation, "enable Vulkan validation layers; any validation error fails the run");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  std::string error;
  auto scene = facet::runtime::loadScene(scenePath, &error);
  if (!scene) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  if (!tier.empty()) scene->tier = tier;
  auto prepared = facet::runtime::SceneFrame::prepare(*scene, packageDir, &error);
  if (!prepared) return fail(scenePath + ": " + error);

  std::error_code ec;
  std::filesystem::create_directories(outDir, ec);
  if (ec) return fail("cannot create '" + outDir + "': " + ec.message());
  std::string stem = std::filesystem::path(scenePath).stem().string();
  if (!tier.empty()) stem += "." + tier;

  std::vector<std::string> backends;
  if (backendName == "both" || backendName == "vulkan") backends.push_back("vulkan");
  if (backendName == "both" || backendName == "gl") backends.push_back("gl");
  for (const std::string& name : backends) {
    std::unique_ptr<facet::runtime::RenderBackend> backend =
        name == "vulkan" ? facet::runtime::createVulkanBackend({validation}, &error) : facet::runtime::createGlBackend(&error);
    if (!backend) return fail(name + ": " + error);
    facet::runtime::FrameResult result;
    if (!backend->render(prepared->frame(), &result, &error)) return fail(name + ": " + error);
    for (const std::string& message : backend->validationErrors()) std::fprintf(stderr, "%s validation: %s\n", name.c_str(), message.c_str());
    if (!backend->validationErrors().empty()) return fail(name + ": validation reported errors");
    std::string path = (std::filesystem::path(outDir) / (stem + "." + name + ".png")).string();
    if (!facet::runtime::writePng(path, result.width, result.height, result.ldr, &error)) return fail(error);
    std::printf("%s: %s (%ux%u, variant %s, exposure %.3g)\n", name.c_str(), path.c_str(), result.width, result.height,
                prepared->variantKey().c_str(), prepared->exposure());
  }
  return 0;
}
