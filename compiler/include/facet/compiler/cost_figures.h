// The static figures of a shader stage, by name: the one table of their names, units and
// meanings that every report reads (`matc info`'s cost table and its --json, `matc lint`'s
// table, JSON, budgets and baselines, `matc eval`'s report.json, tools/mesa_stats). A report
// picks the figures it shows by Figure; what a figure is called, in which unit and to how many
// decimals it is printed is written here once (docs/lint.md, "Figures").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "facet/compiler/mobile_cost.h"
#include "facet/compiler/spirv_interface.h"

namespace facet::compiler {

// What the figures of one stage are read from: the mobile cost model's estimate (with the op
// classes and instruction counts of the same walk of the SPIR-V) and the stage's interface. A
// report that never shows an interface figure may leave `interface` empty.
struct StageFigures {
  MobileStageCost mobile;
  StageInterface interface;
  const InstructionCounts& instructions() const { return mobile.counts.instructions; }
};

enum class Figure {
  // Instruction counts and the estimate: `matc info`'s table, lint's budgets and baselines.
  Cycles,
  Alu,
  ScalarAlu,
  Transcendental,
  Divisions,
  Textures,
  VaryingComponents,
  RelaxedPercent,
  // The stage's interface (lint).
  InputVectors,
  OutputVectors,
  UniformVectors,
  Samplers,
  // The cost model's inside (`matc eval`).
  Bound,
  ArithmeticCycles,
  TextureCycles,
  VaryingCycles,
  FmaSlots,
  CvtSlots,
  SfuOps,
  TextureSamples,
  VaryingChannels,
  ScalarTranscendentals,
  ScalarDivisions,
  // Op-class counts beside OpClass's own (toString(OpClass)).
  FmaRelaxed,
  FragmentVaryings,
  FragmentVaryingsRelaxed,
  Count,
};

struct CostFigure {
  Figure figure;
  const char* name;    // JSON key, budget and baseline name: "scalar_alu"
  const char* column;  // heading in text tables ("scalar"); "" when no text table shows it
  const char* unit;    // "cycles", "instructions", "%", ...
  int decimals;        // as text tables print it; lint's budgets and baselines compare at this precision
  bool integer;        // held as an integer count: JSON writes it without a fraction
  const char* description;
  double (*value)(const StageFigures&);      // nullptr for a figure that is a word (text)
  const char* (*text)(const StageFigures&);  // the word, for Bound; else nullptr
};

std::span<const CostFigure> costFigures();  // every figure, in Figure order
const CostFigure& costFigure(Figure figure);
const CostFigure* findCostFigure(const std::string& name);  // nullptr for a name no figure has

// The figure as a JSON value (Json: nlohmann::json or ordered_json): a number, an integer for an
// integer figure, or the word.
template <typename Json>
Json figureJson(const CostFigure& figure, const StageFigures& stage) {
  if (figure.text) return Json(figure.text(stage));
  const double value = figure.value(stage);
  return figure.integer ? Json(uint64_t(value)) : Json(value);
}

// The value as text tables print it, so that what lint compares is what a reader sees
// (cycles in hundredths).
double reportedValue(const CostFigure& figure, const StageFigures& stage);

// Text tables: "  <variant> <stage>" and one right-aligned cell per column, as `matc info` and
// `matc lint` print them. The widths are the report's; names, headings and precision the table's.
struct FigureColumn {
  Figure figure;
  int width;
};
std::string figureTableHeading(std::span<const FigureColumn> columns);
std::string figureTableRow(const std::string& variant, const char* stage, std::span<const FigureColumn> columns,
                           const StageFigures& figures);
// The cell of one figure: decimals as the table says, "%" after a percentage.
std::string formatFigure(const CostFigure& figure, double value);

}  // namespace facet::compiler
