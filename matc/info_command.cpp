#include <algorithm>
#include <cstdio>
#include <cstring>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "facet/cli/inputs.h"
#include "facet/compiler/cost_figures.h"
#include "facet/compiler/spirv_tools_backend.h"
#include "facet/package/checks.h"
#include "facet/package/package.h"
#include "facet/scene/scene.h"
#include "scene_keys.h"

namespace facet::matc {
namespace {

std::string formatValue(const std::vector<double>& v) {
  std::string s;
  char buf[32];
  for (size_t i = 0; i < v.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%g", i ? ", " : "", v[i]);
    s += buf;
  }
  return v.size() > 1 ? "(" + s + ")" : s;
}

std::vector<uint32_t> words(const package::Shader& s) {
  std::vector<uint32_t> w(s.code.size() / 4);
  std::memcpy(w.data(), s.code.data(), w.size() * 4);
  return w;
}

// The static cost table (docs/specular-tiers.md, "Static cost"), from each variant's optimised SPIR-V, with the
// mobile cost model's estimated cycles (docs/eval.md, "The mobile cost model"). --json carries the same figures.
using compiler::Figure;
constexpr compiler::FigureColumn kCostColumns[] = {
    {Figure::Alu, 5},      {Figure::ScalarAlu, 6},         {Figure::Transcendental, 6}, {Figure::Divisions, 4},
    {Figure::Textures, 4}, {Figure::VaryingComponents, 8}, {Figure::RelaxedPercent, 8}, {Figure::Cycles, 7},
};

// The figures of a variant's SPIR-V shader; false with *error when the cost model cannot read it.
bool stageFigures(const package::Shader& s, compiler::StageFigures* figures, std::string* error) {
  return compiler::estimateMobileCost(words(s), &figures->mobile, error);
}

void printCosts(const package::Package& pkg) {
  std::printf(
      "static cost (optimised SPIR-V; scalar = ALU ops weighted by vector width; cycles = estimated\n"
      "Valhall-class cycles per vertex or fragment, docs/eval.md)\n");
  std::fputs(compiler::figureTableHeading(kCostColumns).c_str(), stdout);
  for (const package::Variant& v : pkg.variants) {
    for (const package::Shader& s : v.shaders) {
      if (s.target != package::Target::Spirv) continue;
      compiler::StageFigures figures;
      std::string error;
      if (!stageFigures(s, &figures, &error)) {
        std::printf("  %-18s %-8s (%s)\n", v.key.c_str(), package::toString(s.stage), error.c_str());
        continue;
      }
      std::fputs(compiler::figureTableRow(v.key, package::toString(s.stage), kCostColumns, figures).c_str(), stdout);
    }
  }
}

// The cost table's figures of each variant's SPIR-V stages, by the cost model's names, exact
// (the text table rounds): {"vertex": {"alu": 90, ...}, "fragment": {...}}, or
// {"<stage>": {"error": "..."}} where the cost model cannot read the code.
nlohmann::ordered_json costsJson(const package::Variant& v) {
  nlohmann::ordered_json costs = nlohmann::ordered_json::object();
  for (const package::Shader& s : v.shaders) {
    if (s.target != package::Target::Spirv) continue;
    compiler::StageFigures figures;
    std::string error;
    nlohmann::ordered_json stage = nlohmann::ordered_json::object();
    if (!stageFigures(s, &figures, &error)) {
      stage["error"] = error;
    } else {
      for (const compiler::FigureColumn& c : kCostColumns) {
        const compiler::CostFigure& f = compiler::costFigure(c.figure);
        stage[f.name] = compiler::figureJson<nlohmann::ordered_json>(f, figures);
      }
    }
    costs[package::toString(s.stage)] = std::move(stage);
  }
  return costs;
}

// Where a Metal app binds each block and sampler (section MSLB): pinned from the shader ABI, so
// one table holds for every variant. Blocks at [[buffer(n)]]; a sampler at [[texture(n)]] and
// [[sampler(n)]]. The Vulkan set/binding of the same resource lets an engine map one to the other.
void printMslSlots(const package::Package& pkg) {
  if (pkg.mslBindings.empty()) {
    std::printf("msl slots  none recorded (a package before format 1.2)\n");
    return;
  }
  std::printf("msl slots  %zu (every variant: blocks at [[buffer(n)]], samplers at [[texture(n)]] + [[sampler(n)]])\n",
              pkg.mslBindings.size());
  for (const package::MslBinding& b : pkg.mslBindings) {
    const std::string slot = std::string(package::toString(b.kind)) + "(" + std::to_string(b.index) + ")";
    std::printf("  %-28s %-12s Vulkan set %u binding %u\n", b.name.c_str(), slot.c_str(), b.set, b.binding);
  }
}

// The keys of the package's depth-only programs (`<tier>.depth`), in package order.
std::vector<std::string> depthPrograms(const package::Package& pkg) {
  std::vector<std::string> keys;
  for (const package::Variant& v : pkg.variants)
    if (package::isDepthProgramKey(v.key)) keys.push_back(v.key);
  return keys;
}

void printSummary(const package::ReadResult& r) {
  const package::Package& pkg = *r.package;
  const package::MaterialInfo& m = pkg.material;
  std::printf("material   %s\n", m.name.c_str());
  std::printf("shading    %s\nblending   %s\n", m.shading.c_str(), m.blending.c_str());
  std::printf("compiler   %s\n", pkg.compilerVersion.c_str());
  std::printf("format     %u.%u\n", unsigned(r.formatMajor), unsigned(r.formatMinor));
  std::printf("parameters %zu (uniform block MaterialParams, %u bytes std140)\n", m.params.size(), m.paramBlockSize);
  for (const package::Param& p : m.params) {
    std::string range;
    if (p.rangeMin && p.rangeMax)
      range = " in [" + formatValue({*p.rangeMin}) + ", " + formatValue({*p.rangeMax}) + "]";
    // Where the value lives: a std140 offset+size in the block, a sampler slot, or nowhere.
    std::string where;
    if (package::isTexture(p.type))
      where = p.offset == package::kNoTextureSlot ? "unsampled" : "sampler slot " + std::to_string(p.offset);
    else
      where = p.size == 0 ? "unread" : "@" + std::to_string(p.offset) + "+" + std::to_string(p.size);
    std::printf("  %-16s %-6s = %s%s  %s%s\n", p.name.c_str(), package::toString(p.type),
                formatValue(p.defaultValue).c_str(), range.c_str(), where.c_str(),
                p.type == package::ParamType::Color ? "  (default shown linear)" : "");
  }
  // The preshader (format 1.3): which variants read derived members, and how many ops compute them.
  for (const package::PreshaderProgram& program : pkg.preshader.programs) {
    std::string users;
    for (uint32_t v : program.variants) users += (users.empty() ? "" : ", ") + pkg.variants[v].key;
    std::printf("preshader  %zu ops, block %u bytes with the derived inputs, for %s\n", program.ops.size(),
                pkg.preshader.blockSize, users.c_str());
  }
  std::printf("variants   %zu\n", pkg.variants.size());
  for (size_t i = 0; i < pkg.variants.size(); ++i) {
    const package::Variant& v = pkg.variants[i];
    std::printf("  %s\n", v.key.c_str());
    for (size_t j = 0; j < v.shaders.size(); ++j) {
      const package::Shader& s = v.shaders[j];
      const package::ShaderStats& st = r.stats[i][j];
      std::printf("    %-8s %-11s %7llu bytes (%llu stored)\n", package::toString(s.stage), package::toString(s.target),
                  static_cast<unsigned long long>(st.rawSize), static_cast<unsigned long long>(st.storedSize));
    }
  }
  // The shadow pass's programs (format 1.7), among the variants above.
  if (std::vector<std::string> depth = depthPrograms(pkg); !depth.empty()) {
    std::string keys;
    for (const std::string& k : depth) keys += (keys.empty() ? "" : ", ") + k;
    std::string reads = pkg.material.blending == "masked" ? "position and the alpha test" : "position only";
    if (keys.find(".depth.slope") != std::string::npos)
      reads += "; .depth.slope also the normal, for the vertex-stage slope bias";
    std::printf("depth      %zu depth-only program%s for the shadow pass (%s): %s\n", depth.size(),
                depth.size() == 1 ? "" : "s", reads.c_str(), keys.c_str());
  }
  if (!pkg.textures.empty()) std::printf("textures   %zu\n", pkg.textures.size());
  for (size_t i = 0; i < pkg.textures.size(); ++i) {
    const package::Texture& t = pkg.textures[i];
    std::string users;
    for (uint32_t v : t.variants) users += (users.empty() ? "" : ", ") + pkg.variants[v].key;
    std::printf("  %s %s %ux%u, sampled by %s, %llu bytes (%llu stored)\n", t.name.c_str(), package::toString(t.format),
                t.width, t.height, users.empty() ? "no variant" : users.c_str(),
                static_cast<unsigned long long>(r.textureStats[i].rawSize),
                static_cast<unsigned long long>(r.textureStats[i].storedSize));
  }
  if (r.dictionaryStoredSize > 0)
    std::printf("dictionary %llu bytes stored (shared by the shaders compressed against it)\n",
                static_cast<unsigned long long>(r.dictionaryStoredSize));
  printMslSlots(pkg);
  printCosts(pkg);
}

// The summary as one JSON document, for scripts and build tools: what printSummary shows, with
// sizes as numbers and each variant's static cost figures (docs/build-integration.md).
void printJson(const package::ReadResult& r) {
  const package::Package& pkg = *r.package;
  nlohmann::ordered_json doc;
  doc["material"] = pkg.material.name;
  doc["shading"] = pkg.material.shading;
  doc["blending"] = pkg.material.blending;
  doc["compiler"] = pkg.compilerVersion;
  doc["format"] = std::to_string(r.formatMajor) + "." + std::to_string(r.formatMinor);
  doc["paramBlockSize"] = pkg.material.paramBlockSize;
  doc["parameters"] = nlohmann::ordered_json::array();
  for (const package::Param& p : pkg.material.params) {
    nlohmann::ordered_json param{{"name", p.name}, {"type", package::toString(p.type)}, {"default", p.defaultValue}};
    if (p.rangeMin) param["min"] = *p.rangeMin;
    if (p.rangeMax) param["max"] = *p.rangeMax;
    if (package::isTexture(p.type)) {
      param["samplerSlot"] =
          p.offset == package::kNoTextureSlot ? nlohmann::ordered_json() : nlohmann::ordered_json(p.offset);
    } else {
      param["offset"] = p.offset;
      param["size"] = p.size;
    }
    doc["parameters"].push_back(std::move(param));
  }
  doc["variants"] = nlohmann::ordered_json::array();
  for (size_t i = 0; i < pkg.variants.size(); ++i) {
    nlohmann::ordered_json shaders = nlohmann::ordered_json::array();
    for (size_t j = 0; j < pkg.variants[i].shaders.size(); ++j) {
      const package::Shader& s = pkg.variants[i].shaders[j];
      shaders.push_back({{"stage", package::toString(s.stage)},
                         {"target", package::toString(s.target)},
                         {"bytes", r.stats[i][j].rawSize},
                         {"storedBytes", r.stats[i][j].storedSize}});
    }
    doc["variants"].push_back(
        {{"key", pkg.variants[i].key}, {"shaders", std::move(shaders)}, {"costs", costsJson(pkg.variants[i])}});
  }
  doc["depthPrograms"] = depthPrograms(pkg);
  doc["textures"] = nlohmann::ordered_json::array();
  for (size_t i = 0; i < pkg.textures.size(); ++i) {
    const package::Texture& t = pkg.textures[i];
    nlohmann::ordered_json users = nlohmann::ordered_json::array();
    for (uint32_t v : t.variants) users.push_back(pkg.variants[v].key);
    doc["textures"].push_back({{"name", t.name},
                               {"format", package::toString(t.format)},
                               {"width", t.width},
                               {"height", t.height},
                               {"variants", std::move(users)},
                               {"bytes", r.textureStats[i].rawSize},
                               {"storedBytes", r.textureStats[i].storedSize}});
  }
  // The preshader (format 1.3): the block with the derived inputs, and each program's users.
  doc["preshadedBlockSize"] = pkg.preshader.programs.empty() ? pkg.material.paramBlockSize : pkg.preshader.blockSize;
  doc["preshaderPrograms"] = nlohmann::ordered_json::array();
  for (const package::PreshaderProgram& program : pkg.preshader.programs) {
    nlohmann::ordered_json users = nlohmann::ordered_json::array();
    for (uint32_t v : program.variants) users.push_back(pkg.variants[v].key);
    doc["preshaderPrograms"].push_back({{"ops", program.ops.size()}, {"variants", std::move(users)}});
  }
  doc["dictionaryStoredBytes"] = r.dictionaryStoredSize;
  doc["mslSlots"] = nlohmann::ordered_json::array();
  for (const package::MslBinding& b : pkg.mslBindings) {
    doc["mslSlots"].push_back({{"name", b.name},
                               {"kind", package::toString(b.kind)},
                               {"index", b.index},
                               {"set", b.set},
                               {"binding", b.binding}});
  }
  std::printf("%s\n", doc.dump(2).c_str());
}

int printShader(const package::Package& pkg, const InfoArgs& args) {
  for (const package::Variant& v : pkg.variants) {
    if (v.key != args.variant) continue;
    for (const package::Shader& s : v.shaders) {
      if (args.stage != package::toString(s.stage) || args.target != package::toString(s.target)) continue;
      if (s.target == package::Target::Spirv) {
        std::fputs(compiler::disassembleSpirv(words(s)).c_str(), stdout);
      } else {
        std::fwrite(s.code.data(), 1, s.code.size(), stdout);
      }
      return 0;
    }
    cli::printError("variant '" + args.variant + "' has no " + args.stage + " shader for target " + args.target);
    return 1;
  }
  std::string keys;
  for (const package::Variant& v : pkg.variants) keys += (keys.empty() ? "" : ", ") + v.key;
  cli::printError("package has no variant '" + args.variant + "' (it has: " + keys + ")");
  return 1;
}

// Which of the package's variants a scene asks for: the count with and without the scene, and a
// clear error (exit 1) when the package lacks it.
int printSceneNeeds(const package::Package& pkg, const std::string& scenePath) {
  std::string error;
  auto scene = loadSceneManifest(scenePath, &error);
  if (!scene) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const permutations::MaterialNeeds needs{pkg.material.shading == "lit",
                                          permutations::blendingCastsShadows(pkg.material.blending)};
  auto keys = sceneKeysFor(*scene, scenePath, pkg.material.name, needs, &error);
  if (!keys) {
    cli::printError(error);
    return 1;
  }
  std::string missing;
  for (const permutations::VariantKey& key : *keys) {
    bool built = std::any_of(pkg.variants.begin(), pkg.variants.end(),
                             [&](const package::Variant& v) { return v.key == key.toString(); });
    std::printf("%s: scene %s asks for %s; the package has %zu variant%s%s\n", pkg.material.name.c_str(),
                scenePath.c_str(), key.toString().c_str(), pkg.variants.size(), pkg.variants.size() == 1 ? "" : "s",
                built ? ", including it" : "");
    if (!built) missing += (missing.empty() ? "" : ", ") + key.toString();
  }
  if (missing.empty()) return 0;
  cli::printError("the package was not built with " + missing + "; compile with --scene " + scenePath);
  return 1;
}

// What an app loading the package would be told, by the loader's own checks (one implementation,
// facet/package/checks.h: loadError for the tables and the format, checkVariant on every variant
// for the code: SPIR-V validation, stages, interfaces), none of which needs a GPU; "" when every
// variant loads. The GLSL ES text is checked by a GL driver only, so not here.
std::string runtimeRefusal(const std::string& path) {
  std::string error;
  std::optional<package::PackageReader> reader = package::PackageReader::openFile(path, &error);
  if (!reader) return error;
  if (std::string why = package::loadError(*reader); !why.empty()) return why;
  return package::checkEveryVariant(*reader, &error) ? "" : error;
}

int describe(const package::ReadResult& r, const InfoArgs& args) {
  if (!args.variant.empty()) return printShader(*r.package, args);
  if (!args.scene.empty()) return printSceneNeeds(*r.package, args.scene);
  if (args.json) {
    printJson(r);
  } else {
    printSummary(r);
  }
  return 0;
}

}  // namespace

int infoCommand(const InfoArgs& args) {
  bool wantsShader = !args.variant.empty() || !args.stage.empty() || !args.target.empty();
  if (wantsShader && (args.variant.empty() || args.stage.empty() || args.target.empty())) {
    cli::printError("to print a shader, give --variant, --stage and --target together");
    return 2;
  }
  package::ReadResult r = package::readFile(args.input);
  if (!r.package) {
    std::fprintf(stderr, "%s: error: %s\n", args.input.c_str(), r.error.c_str());
    return 1;
  }
  // What the package holds is printed either way (it helps to see what a refused package is);
  // the exit status says whether an app would draw it.
  const int described = describe(r, args);
  if (std::string refusal = runtimeRefusal(args.input); !refusal.empty()) {
    std::fprintf(stderr, "%s: error: the runtime refuses this package: %s\n", args.input.c_str(), refusal.c_str());
    return 1;
  }
  return described;
}

}  // namespace facet::matc
