#include "facet/lint/lint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <tuple>

#include "facet/compiler/build.h"
#include "facet/gpu_stats/package_pairs.h"
#include "facet/ir/check.h"
#include "facet/ir/passes.h"
#include "facet/lint/precision_rules.h"
#include "facet/package/package.h"
#include "facet/permutations/tiers.h"

namespace facet::lint {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

const std::vector<uint32_t>* spirvOf(const package::Variant& v, package::Stage stage, std::vector<uint32_t>* storage) {
  for (const package::Shader& s : v.shaders) {
    if (s.stage != stage || s.target != package::Target::Spirv) continue;
    storage->assign(s.code.size() / 4, 0);
    for (size_t i = 0; i < storage->size(); ++i)
      (*storage)[i] = uint32_t(s.code[4 * i]) | uint32_t(s.code[4 * i + 1]) << 8 | uint32_t(s.code[4 * i + 2]) << 16 |
                      uint32_t(s.code[4 * i + 3]) << 24;
    return storage;
  }
  return nullptr;
}

// The rules over one variant's figures. Findings name the material and variant in their message:
// they have no line in the material.
class VariantRules {
 public:
  VariantRules(const std::string& material, const LintOptions& options, std::vector<ir::Diagnostic>* out)
      : material_(material), options_(options), out_(out) {}

  void run(const VariantFigures& v) {
    for (auto [name, figures] : {std::pair{"vertex", &v.vertex}, {"fragment", &v.fragment}}) {
      glesLimits(v.key, name, *figures);
      highpInputs(v.key, name, *figures);
      budget(v.key, name, *figures);
      baseline(v.key, name, *figures);
    }
    shadowPrecision(v.key, "vertex", v.shadow.vertexRelaxed);
    shadowPrecision(v.key, "fragment", v.shadow.fragmentRelaxed);
  }

 private:
  void finding(ir::Severity severity, std::string message, std::string rule) {
    out_->push_back({severity, ir::SourceLoc{}, std::move(message), std::move(rule)});
  }

  std::string where(const std::string& key, const char* stage) const {
    return "material '" + material_ + "' variant " + key + " " + stage + " stage";
  }

  // GLES 3.0's guaranteed minimums: a variant above one fails to link on some device.
  void glesLimits(const std::string& key, const char* stage, const StageFigures& f) {
    using L = compiler::Gles30Limits;
    bool vertex = std::string(stage) == "vertex";
    auto check = [&](uint32_t value, uint32_t limit, const char* what) {
      if (value > limit)
        finding(ir::Severity::Error,
                where(key, stage) + " uses " + std::to_string(value) + " " + what + "; GLES 3.0 guarantees only " +
                    std::to_string(limit),
                "gles-limit");
    };
    check(f.interface.samplers, vertex ? L::kVertexSamplers : L::kFragmentSamplers, "samplers");
    check(f.interface.uniformVectors, vertex ? L::kVertexUniformVectors : L::kFragmentUniformVectors,
          "uniform vectors");
    if (vertex) {
      check(f.interface.inputVectors, L::kVertexAttribs, "vertex attributes");
      check(f.interface.outputVectors, L::kVaryingVectors, "varying vectors");
    } else {
      check(f.interface.inputVectors, L::kVaryingVectors, "varying vectors");
    }
  }

  // The precision policy (docs/architecture.md, "Tiers"): positions and texture coordinates stay
  // highp in every tier (fp16's 11-bit mantissa steps by 1/1024 between 1 and 2: a 2048-texel
  // texture misses every other texel, a position 1 km away moves in 0.5 m steps). Names are the
  // templates' varyings and shader_abi.h's attributes. The vector to the eye (v_toEye) is not
  // among them: only its direction is read, and the mediump tiers send it scaled into binary16's
  // range (chunks/view_vector.glsl; the fp16 hard cases render it 3 km away).
  void highpInputs(const std::string& key, const char* stage, const StageFigures& f) {
    static const std::set<std::string> mustBeHighp = {"v_worldPosition", "v_uv0", "v_uv1",
                                                      "a_position",      "a_uv0", "a_uv1"};
    for (const std::string& name : f.interface.relaxedInputs)
      if (mustBeHighp.count(name))
        finding(ir::Severity::Error,
                where(key, stage) + " reads '" + name + "' in mediump; positions and UVs need highp", "highp-required");
  }

  // A receiver's atlas coordinate and compare depth (shadow_precision.h): fp16 holds neither.
  void shadowPrecision(const std::string& key, const char* stage, const std::vector<std::string>& relaxed) {
    if (relaxed.empty()) return;
    std::string names;
    for (const std::string& name : relaxed) names += (names.empty() ? "" : ", ") + name;
    finding(ir::Severity::Error,
            where(key, stage) + " computes a shadow coordinate or compare depth in mediump (" + names +
                "); atlas coordinates and depths need highp",
            "shadow-precision");
  }

  void budget(const std::string& key, const char* stage, const StageFigures& f) {
    if (!options_.budgets) return;
    auto tier = permutations::VariantKey::parse(key);
    if (!tier) return;
    auto t = options_.budgets->tiers.find(permutations::toString(tier->tier));
    if (t == options_.budgets->tiers.end()) return;
    auto s = t->second.find(stage);
    if (s == t->second.end()) return;
    const StageBudget& b = s->second;
    for (const auto& [name, value] : namedFigures(f)) {
      auto limit = b.max.find(name);
      if (limit != b.max.end() && value > limit->second)
        finding(ir::Severity::Error,
                where(key, stage) + ": " + name + " " + number(value) + " exceeds the " + t->first + " budget " +
                    number(limit->second),
                "budget");
    }
    if (b.minRelaxedPercent && f.instructions().relaxedPercent() < *b.minRelaxedPercent)
      finding(ir::Severity::Error,
              where(key, stage) + ": " + number(f.instructions().relaxedPercent()) +
                  " % of float ops in mediump, below the " + t->first + " budget's " + number(*b.minRelaxedPercent) +
                  " %",
              "budget");
  }

  void baseline(const std::string& key, const char* stage, const StageFigures& f) {
    if (!options_.baseline) return;
    const FigureLimits* recorded = nullptr;
    if (auto m = options_.baseline->materials.find(material_); m != options_.baseline->materials.end())
      if (auto v = m->second.find(key); v != m->second.end())
        if (auto s = v->second.find(stage); s != v->second.end()) recorded = &s->second;
    if (!recorded) {
      finding(ir::Severity::Warning, where(key, stage) + " is not in the baseline; record it with --update-baseline",
              "baseline-missing");
      return;
    }
    for (const auto& [name, value] : namedFigures(f)) {
      auto was = recorded->find(name);
      if (was == recorded->end()) continue;
      // Small figures move by whole ops: allow at least one op of growth, then the tolerance.
      double allowed = std::max(was->second * (1.0 + options_.baselineTolerance), was->second + 1.0);
      if (value > allowed)
        finding(ir::Severity::Error,
                where(key, stage) + ": " + name + " grew from " + number(was->second) + " to " + number(value) + " (+" +
                    number(100.0 * (value - was->second) / std::max(was->second, 1.0)) + " %; tolerance " +
                    number(100.0 * options_.baselineTolerance) + " %)",
                "baseline-regression");
    }
  }

  const std::string& material_;
  const LintOptions& options_;
  std::vector<ir::Diagnostic>* out_;
};

// Reads the SPIR-V of both stages into figures; false with *error when it cannot.
bool variantFigures(const package::Variant& v, VariantFigures* figures, std::string* error) {
  figures->key = v.key;
  std::vector<uint32_t> words[2];
  for (auto [stage, dest, stageWords] : {std::tuple{package::Stage::Vertex, &figures->vertex, &words[0]},
                                         {package::Stage::Fragment, &figures->fragment, &words[1]}}) {
    if (!spirvOf(v, stage, stageWords)) {
      *error = "no SPIR-V";
      return false;
    }
    if (!compiler::estimateMobileCost(*stageWords, &dest->mobile, error) ||
        !compiler::analyseStageInterface(*stageWords, &dest->interface, error))
      return false;
  }
  // The shadow-precision rule's reading of the same code (shadow_precision.h).
  return analyseShadowPrecision(words[0], words[1], &figures->shadow, error);
}

}  // namespace

bool MaterialLint::hasErrors() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const ir::Diagnostic& d) { return d.severity == ir::Severity::Error; });
}

std::span<const compiler::Figure> baselineFigures() {
  using F = compiler::Figure;
  static constexpr F kFigures[] = {F::Cycles,
                                   F::Alu,
                                   F::ScalarAlu,
                                   F::Transcendental,
                                   F::Divisions,
                                   F::Textures,
                                   F::VaryingComponents,
                                   F::InputVectors,
                                   F::OutputVectors,
                                   F::UniformVectors,
                                   F::Samplers};
  return kFigures;
}

std::vector<std::pair<std::string, double>> namedFigures(const StageFigures& s) {
  // Cycles in hundredths, as reports print them: a baseline compares what a reader sees.
  std::vector<std::pair<std::string, double>> named;
  for (compiler::Figure f : baselineFigures()) {
    const compiler::CostFigure& figure = compiler::costFigure(f);
    named.emplace_back(figure.name, compiler::reportedValue(figure, s));
  }
  return named;
}

std::vector<std::string> figureNames() {
  std::vector<std::string> names;
  for (compiler::Figure f : baselineFigures()) names.push_back(compiler::costFigure(f).name);
  return names;
}

MaterialLint lintMaterial(const ir::SourceFile& file, const LintOptions& options) {
  MaterialLint out;
  ir::Diagnostics diags(file);
  std::optional<ir::Material> checked = ir::compileSource(file, diags);
  if (checked) {
    out.material = checked->name;
    ir::Material optimized = *checked;
    ir::optimize(optimized);
    bool mediump = std::any_of(options.tiers.begin(), options.tiers.end(), [](permutations::Tier t) {
      return permutations::preset(t).precision == permutations::PrecisionPolicy::Mediump;
    });
    lint_precision(optimized, mediump, diags);
    // The kernel is min(2 · variance · |∇n|², threshold) (chunks/specular_antialiasing.glsl): with
    // either 0 it adds nothing, and the derivatives still cost every pixel.
    if (const auto& aa = checked->specularAntiAliasing; aa && (aa->variance == 0.0 || aa->threshold == 0.0))
      diags.warning(aa->loc,
                    std::string("specular anti-aliasing with ") + (aa->variance == 0.0 ? "variance" : "threshold") +
                        " 0 filters nothing but still takes the normal's derivatives in every pixel; remove it, "
                        "or drop it per tier with `tier <t> { specular_aa = none }`",
                    "specular-aa-inert");
  }
  out.diagnostics = diags.all();
  if (!checked) return out;

  compiler::BuildOptions build;
  build.tiers = options.tiers;
  build.pointLightCounts = options.pointLightCounts;
  build.shadowCascadeCounts = options.shadowCascadeCounts;
  build.tunedTiers = options.tunedTiers;
  build.spotShadows = options.spotShadows;
  compiler::BuildError error;
  std::optional<compiler::BuildResult> built = compiler::buildMaterial(*checked, build, &error);
  if (!built) {
    out.diagnostics.push_back({ir::Severity::Error, error.loc.value_or(ir::SourceLoc{}), error.message, "backend"});
    return out;
  }
  for (const package::Variant& v : built->package.variants) {
    VariantFigures figures;
    std::string why;
    if (!variantFigures(v, &figures, &why)) {
      out.diagnostics.push_back({ir::Severity::Error, ir::SourceLoc{},
                                 "internal error: cannot analyse the SPIR-V of variant " + v.key + ": " + why,
                                 "backend"});
      continue;
    }
    lintVariant(out.material, figures, options, &out.diagnostics);
    out.variants.push_back(std::move(figures));
  }
  if (!options.gpus.empty())
    out.gpuStats = gpu_stats::measure(gpu_stats::glslEsPairs(built->package), options.gpus, options.mesaTool);
  return out;
}

void lintVariant(const std::string& material, const VariantFigures& figures, const LintOptions& options,
                 std::vector<ir::Diagnostic>* diagnostics) {
  VariantRules(material, options, diagnostics).run(figures);
}

}  // namespace facet::lint
