// matc: the Facet material compiler's command line. Argument parsing and wiring only; the work
// happens in the ir, compiler and package libraries.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <optional>
#include <string>

#include "commands.h"
#include "facet/cli/command_line.h"
#include "facet/package/atomic_file.h"

namespace {

// CLI::Range lets NaN through (no comparison with it is true), and a NaN tolerance turns every
// baseline comparison off: this one takes finite numbers in [min, max] only.
CLI::Validator finiteRange(double min, double max) {
  const std::string range = "[" + CLI::detail::to_string(min) + ", " + CLI::detail::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !(value >= min && value <= max))
          return "Value " + text + " is not a number in " + range;
        return std::string();
      },
      "NUMBER in " + range);
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or a build system's kill during a write leaves no temporary file behind.
  facet::removeTemporaryFilesOnSignals();
  CLI::App app{"matc: compiles Facet materials (.mat) into shader packages (.matpkg)"};
  app.require_subcommand(1);

  facet::matc::CompileArgs compile;
  CLI::App* compileCmd = app.add_subcommand("compile", "compile a material into a .matpkg package");
  compileCmd->add_option("input", compile.input, "material source (.mat)")->required();
  compileCmd->add_option("-o,--output", compile.output, "package to write (default: <input>.matpkg)");
  compileCmd->add_option("--emit-source", compile.emitSource,
                         "also write every generated shader source to this folder (readable GLSL, SPIR-V "
                         "disassembly: produced only with this option)");
  compileCmd->add_option("--depfile", compile.depfile,
                         "also write a Makefile-syntax depfile (package: material, scene, matc, templates and "
                         "chunks used) for Ninja/Make");
  CLI::Option* cacheOption = compileCmd->add_option("--cache", compile.cacheDir,
                                                    "cache of compiled variants (default: $XDG_CACHE_HOME/facet/matc "
                                                    "or ~/.cache/facet/matc); the package is the same "
                                                    "bytes with or without it");
  compileCmd->add_flag("--no-cache", compile.noCache, "neither read nor write the cache")->excludes(cacheOption);
  compileCmd
      ->add_option("--cache-max-size", compile.cacheMaxMiB,
                   "bound on the cache in MiB: least recently used variants are removed after each compile "
                   "(default 512; 0: no bound)")
      ->check(CLI::Range(0u, 1u << 20));
  compileCmd
      ->add_option("-j,--jobs", compile.jobs,
                   "variants compiled at once (default: one per core); the "
                   "package is byte-identical for any value")
      ->check(CLI::Range(1u, 256u));
  compileCmd->add_option("--tiers", compile.tiers, "tiers to build (reference, high, ...); default: all supported")
      ->delimiter(',');
  compileCmd->add_option("--scene", compile.scene, "scene JSON: build only the variants this scene can request");
  compileCmd
      ->add_option("--point-lights", compile.pointLights,
                   "point/spot light counts to build, from 0, 1, 2, 4 (default: 0; a --scene decides its own)")
      ->delimiter(',')
      ->check(CLI::IsMember({0, 1, 2, 4}));
  compileCmd
      ->add_option("--shadows", compile.shadows,
                   "sun shadow cascades to build receivers for (dir1 variants), from 0, 1, 2, 4 (default: 0, none; "
                   "a --scene decides its own)")
      ->delimiter(',')
      ->check(CLI::IsMember({0, 1, 2, 4}));
  CLI::Option* tuningOption = compileCmd->add_option(
      "--tuning", compile.tuning,
      "the tiers' tuning file (matc tune --write; default: <input stem>.tuning.json beside the input, if any)");
  compileCmd->add_flag("--no-tuning", compile.noTuning, "build the tier presets with the material's tier blocks")
      ->excludes(tuningOption);
  compileCmd->add_flag("--spot-shadows", compile.spotShadows,
                       "also build each variant with point lights as a receiver of light slot 0's spot shadow "
                       "(.sp1) and the depth-only programs (default: none; a --scene decides its own)");
  compileCmd->add_flag("--vertex-slope-bias", compile.vertexSlopeBias,
                       "also build each depth-only program with the slope bias in its vertex stage (.depth.slope, "
                       "for a scene's \"slopeStage\": \"vertex\"; default: none; a --scene decides its own)");
  compileCmd->add_flag("--fp16-emulation", compile.fp16Emulation,
                       "testing only: round every mediump result to binary16 in the SPIR-V of mediump tiers "
                       "(docs/fp16-emulation.md); never ship such a package");

  facet::matc::InfoArgs info;
  CLI::App* infoCmd = app.add_subcommand("info", "describe a package, or print one of its shaders");
  infoCmd->add_option("input", info.input, "package (.matpkg)")->required();
  infoCmd->add_option("--variant", info.variant, "variant key, e.g. high.dir1 (with --stage and --target)");
  infoCmd->add_option("--scene", info.scene,
                      "scene JSON: the variant it asks this material for, and whether it is built");
  infoCmd->add_flag("--json", info.json, "print the summary as JSON (sizes, variants, parameters)");
  infoCmd->add_option("--stage", info.stage, "vertex | fragment")->check(CLI::IsMember({"vertex", "fragment"}));
  infoCmd->add_option("--target", info.target, "glsl_es_300 | spirv | msl")
      ->check(CLI::IsMember({"glsl_es_300", "spirv", "msl"}));

  facet::matc::LintArgs lint;
  CLI::App* lintCmd = app.add_subcommand("lint", "check materials' precision and instruction counts (docs/lint.md)");
  lintCmd->add_option("inputs", lint.inputs, "material files (.mat) or folders of them")->required();
  lintCmd->add_option("--tiers", lint.tiers, "tiers to build and check; default: all supported")->delimiter(',');
  lintCmd
      ->add_option("--point-lights", lint.pointLights, "point/spot light counts to check, from 0, 1, 2, 4 (default: 0)")
      ->delimiter(',')
      ->check(CLI::IsMember({0, 1, 2, 4}));
  lintCmd
      ->add_option("--shadows", lint.shadows,
                   "sun shadow cascades to build and check receivers for, from 0, 1, 2, 4 (default: 0, none)")
      ->delimiter(',')
      ->check(CLI::IsMember({0, 1, 2, 4}));
  lintCmd->add_flag("--spot-shadows", lint.spotShadows,
                    "also build and check the spot-shadow receivers (.sp1) of the variants with point lights");
  lintCmd->add_option("--config", lint.config, "budgets per tier and stage (JSON; examples/lint/budgets.json)");
  lintCmd->add_option("--baseline", lint.baseline,
                      "committed figures: fail when a variant's figure grows past the tolerance");
  lintCmd->add_flag("--update-baseline", lint.updateBaseline, "rewrite the --baseline file from this run");
  lintCmd
      ->add_option("--tolerance", lint.tolerancePercent,
                   "growth over the baseline still accepted, in percent (default 5)")
      ->check(finiteRange(0, 1000));
  lintCmd->add_option("--format", lint.format, "text | json | sarif")->check(CLI::IsMember({"text", "json", "sarif"}));
  lintCmd->add_option("-o,--output", lint.output, "write the report to this file instead of standard output");
  lintCmd->add_flag("--werror", lint.werror, "warnings fail the run too");
  lintCmd->add_flag("--no-tuning", lint.noTuning,
                    "check the tier presets, not the tiers of each material's <stem>.tuning.json (matc compile's)");
  lintCmd->add_option(
      "--gpu", lint.gpu,
      "also report Mesa's figures for these GPUs: mali-g52, mali-g57, adreno-630 (docs/mesa-statistics.md)");
  lintCmd->add_option("--mesa-prefix", lint.mesaPrefix,
                      "the Mesa build for --gpu (default: $MESA_PREFIX, else ~/.cache/facet/mesa/install)");
  facet::matc::PostArgs post;
  CLI::App* postCmd = app.add_subcommand("post", "compile the runtime's post pass (both render paths) into C++ source");
  postCmd->add_option("--cpp", post.cpp, "C++ file to write (defines facet::runtime::postShaders())")->required();
  postCmd->add_option("--emit-source", post.emitSource, "also write every generated shader source to this folder");
  postCmd
      ->add_option("--tone-curve", post.toneCurve,
                   "aces (filmic, default) | neutral (Khronos PBR Neutral: keeps hue below its knee) | none (HDR "
                   "clamped to [0, 1])")
      ->check(CLI::IsMember({"aces", "neutral", "none"}));
  postCmd->add_flag("--dither", post.dither, "add triangular noise of one 8-bit step before quantisation (no banding)");
  postCmd->add_flag("--grading", post.grading, "grade the encoded colour through a 3D LUT (the frame gives the LUT)");
  postCmd->add_flag("--vignette", post.vignette, "darken the corners (the frame gives the vignette's uniforms)");
  postCmd->add_flag("--bloom", post.bloom, "composite the bloom chain's image before the tone curve");
  postCmd->add_flag("--every-variant", post.everyVariant,
                    "build every combination of effects into the C++ source (the runtime's build does)");
  // Everything after `eval` is facet-eval's (eval/tool/main.cpp, whose summary this is), --help
  // included: it parses and checks the options.
  CLI::App* evalCmd = app.add_subcommand(
      "eval",
      "render every tier and single-option swap on lavapipe; report error against reference and cost (docs/eval.md)");
  evalCmd->prefix_command();
  evalCmd->set_help_flag();
  // Everything after `tune` is facet-tune's (tune/tool/main.cpp), in the same way.
  CLI::App* tuneCmd = app.add_subcommand(
      "tune", "choose each tier's cheapest configuration that meets its error budget (docs/tune.md)");
  tuneCmd->prefix_command();
  tuneCmd->set_help_flag();
  // Everything after `texture` is facet-texture's (texture/tool/main.cpp), in the same way.
  CLI::App* textureCmd = app.add_subcommand(
      "texture", "encode a PNG into an ASTC KTX2 texture with its mip levels (docs/texture-format.md)");
  textureCmd->prefix_command();
  textureCmd->set_help_flag();
  // Everything after `import` is facet-gltf-import's (runtime/gltf_import/main.cpp), in the same way.
  CLI::App* importCmd = app.add_subcommand(
      "import", "write a glTF file's materials as .mat files and a scene drawing it with them (docs/gltf.md)");
  importCmd->prefix_command();
  importCmd->set_help_flag();

  if (std::optional<int> exit = facet::cli::parseCommandLine(app, argc, argv)) return *exit;
  if (compileCmd->parsed()) return facet::matc::compileCommand(compile);
  if (infoCmd->parsed()) return facet::matc::infoCommand(info);
  if (lintCmd->parsed()) return facet::matc::lintCommand(lint);
  if (postCmd->parsed()) return facet::matc::postCommand(post);
  if (evalCmd->parsed())
    return facet::matc::runHelperProgram(argv[0], "eval", "facet-eval", "facet-eval", evalCmd->remaining());
  if (tuneCmd->parsed())
    return facet::matc::runHelperProgram(argv[0], "tune", "facet-tune", "facet-tune", tuneCmd->remaining());
  if (textureCmd->parsed())
    return facet::matc::runHelperProgram(argv[0], "texture", "facet-texture", "facet-texture", textureCmd->remaining());
  if (importCmd->parsed())
    return facet::matc::runHelperProgram(argv[0], "import", "facet-gltf-import", "facet-gltf-import",
                                         importCmd->remaining());
  return 2;
}
