#include "facet/compiler/cost_figures.h"

#include <cmath>
#include <cstdio>

namespace facet::compiler {
namespace {

using S = const StageFigures&;

// In Figure order (checked below). Names and headings are what reports have always printed:
// baselines, budgets and scripts read them.
constexpr CostFigure kFigures[] = {
    {Figure::Cycles, "cycles", "cycles", "cycles", 2, false,
     "estimated Valhall-class cycles per vertex or fragment: the busiest of the arithmetic, texture and varying "
     "units (the mobile cost model, docs/eval.md)",
     [](S s) { return s.mobile.cycles; }, nullptr},
    {Figure::Alu, "alu", "alu", "instructions", 0, true, "arithmetic, logic, comparison and conversion instructions",
     [](S s) { return double(s.instructions().aluOps); }, nullptr},
    {Figure::ScalarAlu, "scalar_alu", "scalar", "scalar ops", 0, true,
     "the ALU instructions weighted by their result's components (a vec3 multiply is 3)",
     [](S s) { return double(s.instructions().scalarAluOps); }, nullptr},
    {Figure::Transcendental, "transcendental", "transc", "instructions", 0, true,
     "exp, log, pow, sin, cos, sqrt, inversesqrt instructions, and those that contain one (normalize, length)",
     [](S s) { return double(s.instructions().transcendentalOps); }, nullptr},
    {Figure::Divisions, "divisions", "div", "instructions", 0, true,
     "float and integer division and remainder instructions", [](S s) { return double(s.instructions().divisions); },
     nullptr},
    {Figure::Textures, "textures", "tex", "instructions", 0, true, "sample, fetch and gather instructions",
     [](S s) { return double(s.instructions().textureSamples); }, nullptr},
    {Figure::VaryingComponents, "varying_components", "varyings", "components", 0, true,
     "scalar components of the stage's non-built-in inputs",
     [](S s) { return double(s.instructions().varyingComponents); }, nullptr},
    {Figure::RelaxedPercent, "relaxed_percent", "mediump", "%", 0, false,
     "the share of ALU and transcendental instructions whose result is RelaxedPrecision (mediump)",
     [](S s) { return s.instructions().relaxedPercent(); }, nullptr},
    {Figure::InputVectors, "input_vectors", "", "vectors", 0, true,
     "vec4 slots of the stage inputs: vertex attributes, or varyings",
     [](S s) { return double(s.interface.inputVectors); }, nullptr},
    {Figure::OutputVectors, "output_vectors", "", "vectors", 0, true,
     "vec4 slots of the stage outputs: varyings, or colour outputs",
     [](S s) { return double(s.interface.outputVectors); }, nullptr},
    {Figure::UniformVectors, "uniform_vectors", "uniforms", "vectors", 0, true,
     "vec4 slots of the uniform blocks the stage's code reaches (std140)",
     [](S s) { return double(s.interface.uniformVectors); }, nullptr},
    {Figure::Samplers, "samplers", "samplers", "samplers", 0, true, "combined image samplers, array elements counted",
     [](S s) { return double(s.interface.samplers); }, nullptr},
    {Figure::Bound, "bound", "", "unit", 0, false, "the unit that sets the estimate: arithmetic, texture or varying",
     nullptr, [](S s) { return s.mobile.bound(); }},
    {Figure::ArithmeticCycles, "arithmetic_cycles", "", "cycles", 2, false,
     "the busiest arithmetic pipe (FMA, CVT, SFU) over its issue rate", [](S s) { return s.mobile.arithmeticCycles; },
     nullptr},
    {Figure::TextureCycles, "texture_cycles", "", "cycles", 2, false, "texture instructions over the texture rate",
     [](S s) { return s.mobile.textureCycles; }, nullptr},
    {Figure::VaryingCycles, "varying_cycles", "", "cycles", 2, false,
     "16-bit varying channels over the interpolation rate", [](S s) { return s.mobile.varyingCycles; }, nullptr},
    {Figure::FmaSlots, "fma_slots", "", "FMA slots", 2, false,
     "FMA-pipe slots, expansions included (a mediump op weighs relaxedFmaWeight)",
     [](S s) { return s.mobile.fmaSlots; }, nullptr},
    {Figure::CvtSlots, "cvt_slots", "", "CVT slots", 2, false, "CVT-pipe slots", [](S s) { return s.mobile.cvtSlots; },
     nullptr},
    {Figure::SfuOps, "sfu_ops", "", "SFU ops", 2, false, "special-function ops, expansions included",
     [](S s) { return s.mobile.sfuOps; }, nullptr},
    {Figure::TextureSamples, "texture_samples", "", "instructions", 0, false,
     "the texture instructions the model charges to the texture unit", [](S s) { return s.mobile.textureSamples; },
     nullptr},
    {Figure::VaryingChannels, "varying_channels_16bit", "", "16-bit channels", 0, false,
     "16-bit channels interpolated (a mediump component is 1, a highp one 2)",
     [](S s) { return s.mobile.varyingChannels; }, nullptr},
    {Figure::ScalarTranscendentals, "scalar_transcendentals", "", "scalar ops", 0, false,
     "the model's ops with a special-function part, per scalar component, divisions and derivatives aside",
     [](S s) { return s.mobile.transcendentals(); }, nullptr},
    {Figure::ScalarDivisions, "scalar_divisions", "", "scalar ops", 0, false,
     "the model's float and integer divisions by a value that is not a constant, per scalar component",
     [](S s) { return s.mobile.divisions(); }, nullptr},
    {Figure::FmaRelaxed, "fma_relaxed", "", "scalar ops", 0, false,
     "the part of the fma op class whose result is RelaxedPrecision (mediump)",
     [](S s) { return s.mobile.counts.fmaRelaxed; }, nullptr},
    {Figure::FragmentVaryings, "varyings", "", "components", 0, true,
     "fragment stage: scalar components of its highp inputs",
     [](S s) { return double(s.mobile.counts.varyingComponents); }, nullptr},
    {Figure::FragmentVaryingsRelaxed, "varyings_relaxed", "", "components", 0, true,
     "fragment stage: scalar components of its mediump (RelaxedPrecision) inputs",
     [](S s) { return double(s.mobile.counts.varyingComponentsRelaxed); }, nullptr},
};
static_assert(std::size(kFigures) == size_t(Figure::Count));

constexpr bool inFigureOrder() {
  for (size_t i = 0; i < std::size(kFigures); ++i)
    if (kFigures[i].figure != Figure(i)) return false;
  return true;
}
static_assert(inFigureOrder(), "kFigures must list the figures in Figure order");

std::string padLeft(const std::string& s, int width) {
  return s.size() < size_t(width) ? std::string(size_t(width) - s.size(), ' ') + s : s;
}

std::string padRight(const std::string& s, int width) {
  return s.size() < size_t(width) ? s + std::string(size_t(width) - s.size(), ' ') : s;
}

std::string rowStart(const std::string& variant, const std::string& stage) {
  return "  " + padRight(variant, 18) + " " + padRight(stage, 8);
}

}  // namespace

std::span<const CostFigure> costFigures() { return kFigures; }

const CostFigure& costFigure(Figure figure) { return kFigures[size_t(figure)]; }

const CostFigure* findCostFigure(const std::string& name) {
  for (const CostFigure& f : kFigures)
    if (name == f.name) return &f;
  return nullptr;
}

double reportedValue(const CostFigure& figure, const StageFigures& stage) {
  const double scale = std::pow(10.0, figure.decimals);
  return std::round(figure.value(stage) * scale) / scale;
}

std::string formatFigure(const CostFigure& figure, double value) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f%s", figure.decimals, value, std::string(figure.unit) == "%" ? "%" : "");
  return buf;
}

std::string figureTableHeading(std::span<const FigureColumn> columns) {
  std::string line = rowStart("variant", "stage");
  for (const FigureColumn& c : columns) line += " " + padLeft(costFigure(c.figure).column, c.width);
  return line + "\n";
}

std::string figureTableRow(const std::string& variant, const char* stage, std::span<const FigureColumn> columns,
                           const StageFigures& figures) {
  std::string line = rowStart(variant, stage);
  for (const FigureColumn& c : columns) {
    const CostFigure& f = costFigure(c.figure);
    line += " " + padLeft(f.text ? f.text(figures) : formatFigure(f, f.value(figures)), c.width);
  }
  return line + "\n";
}

}  // namespace facet::compiler
