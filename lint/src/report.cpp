#include "facet/lint/report.h"

#include <cctype>
#include <cstdio>
#include <map>

#include <nlohmann/json.hpp>

#include "facet/gpu_stats/report.h"

namespace facet::lint {
namespace {

using json = nlohmann::json;

const char* severity(const ir::Diagnostic& d) { return d.severity == ir::Severity::Error ? "error" : "warning"; }

// What each lint rule checks, for SARIF's rule metadata (language rules keep the compiler's ids).
const std::map<std::string, std::string>& lintRules() {
  static const std::map<std::string, std::string> rules = {
      {"fp16-constant", "A constant outside binary16's normal range in a mediump expression."},
      {"fp16-overflow", "A mediump value whose proven range leaves fp16's ±65504."},
      {"unranged-param", "A float parameter without a declared range, read by a mediump tier."},
      {"division-bound", "A divisor whose range reaches 0, or below 2^-14 in mediump."},
      {"domain", "sqrt, log2, pow or smoothstep outside the domain GLSL defines."},
      {"direction-length",
       "A direction the shaders normalize in mediump whose squared length can flush to 0 or overflow in fp16."},
      {"reserved-name", "A name GLSL reserves."},
      {"highp-required", "A position or texture coordinate read in mediump."},
      {"gles-limit", "A variant needs more than OpenGL ES 3.0 guarantees."},
      {"budget", "A variant exceeds its tier's budget."},
      {"baseline-regression", "A variant's cost grew over the committed baseline."},
      {"baseline-missing", "A variant the baseline does not record."},
      {"backend", "The shader toolchain rejected generated code."},
  };
  return rules;
}

// RFC 3986: keep unreserved characters and '/', percent-encode the rest.
std::string uriPath(const std::string& path) {
  std::string out;
  for (unsigned char c : path) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      out += char(c);
    } else {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%%%02X", c);
      out += buf;
    }
  }
  return out;
}

// A GPU Mesa could not measure: the calibrated estimate of each variant's fragment figure
// (compiler/mobile_cost.h, calibratedEstimate), or nullptr when the GPU has no calibration.
const compiler::GpuCalibration* estimateFor(const gpu_stats::GpuStats& g) {
  return g.unavailable.empty() ? nullptr : compiler::findGpuCalibration(g.gpu);
}

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * fraction);
  return buf;
}

json figuresJson(const StageFigures& s) {
  json j = json::object();
  for (const auto& [name, value] : namedFigures(s)) j[name] = value;
  const compiler::CostFigure& relaxed = compiler::costFigure(compiler::Figure::RelaxedPercent);
  j[relaxed.name] = relaxed.value(s);
  return j;
}

// The text table's columns.
using compiler::Figure;
constexpr compiler::FigureColumn kTextColumns[] = {
    {Figure::Cycles, 6},
    {Figure::Alu, 4},
    {Figure::ScalarAlu, 6},
    {Figure::Transcendental, 6},
    {Figure::Divisions, 4},
    {Figure::Textures, 4},
    {Figure::VaryingComponents, 8},
    {Figure::UniformVectors, 8},
    {Figure::Samplers, 8},
    {Figure::RelaxedPercent, 8},
};

}  // namespace

std::string formatText(const std::vector<LintedFile>& files) {
  std::string out;
  size_t errors = 0, warnings = 0;
  for (const LintedFile& f : files) {
    for (const ir::Diagnostic& d : f.result.diagnostics) {
      out += ir::formatDiagnostic(f.file, d);
      (d.severity == ir::Severity::Error ? errors : warnings)++;
    }
  }
  for (const LintedFile& f : files) {
    if (f.result.variants.empty()) continue;
    out += "\n" + f.file.path + " (" + f.result.material + ")\n";
    out += compiler::figureTableHeading(kTextColumns);
    for (const VariantFigures& v : f.result.variants)
      for (auto [name, s] : {std::pair{"vertex", &v.vertex}, {"fragment", &v.fragment}})
        out += compiler::figureTableRow(v.key, name, kTextColumns, *s);
    if (!f.result.gpuStats.empty()) out += "  " + gpu_stats::sourceNote(f.result.gpuStats) + "\n";
    for (const gpu_stats::GpuStats& g : f.result.gpuStats) {
      if (const compiler::GpuCalibration* c = estimateFor(g)) {
        out += "  " + g.gpu + ": calibrated estimate of " + c->measure +
               " from the op counts instead (cross-validated error " + percent(c->crossValidatedMeanError) + " mean, " +
               percent(c->crossValidatedMaxError) + " max; docs/mesa-statistics.md)\n";
        for (const VariantFigures& v : f.result.variants) {
          char line[96];
          std::snprintf(line, sizeof line, "    %-18s fragment         %.2f\n", v.key.c_str(),
                        compiler::calibratedEstimate(v.fragment.mobile.counts, *c));
          out += line;
        }
      }
      if (!g.unavailable.empty()) continue;
      out += "  " + g.gpu + " (" + g.renderer + ")\n";
      for (const auto& [key, stages] : g.shaders)
        for (const gpu_stats::StageStats& s : stages) {
          char head[64];
          std::snprintf(head, sizeof head, "    %-18s %-16s ", key.c_str(), s.stage.c_str());
          out += head + gpu_stats::describe(s) + "\n";
        }
    }
  }
  out += "\n" + std::to_string(errors) + " error" + (errors == 1 ? "" : "s") + ", " + std::to_string(warnings) +
         " warning" + (warnings == 1 ? "" : "s") + "\n";
  return out;
}

std::string formatJson(const std::vector<LintedFile>& files) {
  json root = json::object();
  root["files"] = json::array();
  size_t errors = 0, warnings = 0;
  for (const LintedFile& f : files) {
    json jf = json::object();
    jf["path"] = f.file.path;
    jf["material"] = f.result.material;
    jf["diagnostics"] = json::array();
    for (const ir::Diagnostic& d : f.result.diagnostics) {
      json jd = {{"severity", severity(d)}, {"rule", d.code}, {"message", d.message}};
      if (d.loc.line) {
        jd["line"] = d.loc.line;
        jd["column"] = d.loc.column;
      }
      jf["diagnostics"].push_back(jd);
      (d.severity == ir::Severity::Error ? errors : warnings)++;
    }
    jf["variants"] = json::array();
    for (const VariantFigures& v : f.result.variants)
      jf["variants"].push_back(
          {{"key", v.key}, {"vertex", figuresJson(v.vertex)}, {"fragment", figuresJson(v.fragment)}});
    if (!f.result.gpuStats.empty()) {
      jf["gpus"] = json::array();
      for (const gpu_stats::GpuStats& g : f.result.gpuStats) {
        json jg = gpu_stats::toJson(g);
        if (const compiler::GpuCalibration* c = estimateFor(g)) {
          json estimate = {{"measure", c->measure},
                           {"cross_validated_mean_error", c->crossValidatedMeanError},
                           {"cross_validated_max_error", c->crossValidatedMaxError},
                           {"variants", json::object()}};
          for (const VariantFigures& v : f.result.variants)
            estimate["variants"][v.key] = compiler::calibratedEstimate(v.fragment.mobile.counts, *c);
          jg["calibrated_estimate"] = estimate;
        }
        jf["gpus"].push_back(jg);
      }
    }
    root["files"].push_back(jf);
  }
  root["errors"] = errors;
  root["warnings"] = warnings;
  return root.dump(2) + "\n";
}

std::string formatSarif(const std::vector<LintedFile>& files, const std::string& toolVersion) {
  json rules = json::array();
  for (const auto& [id, text] : lintRules()) rules.push_back({{"id", id}, {"shortDescription", {{"text", text}}}});
  json results = json::array();
  for (const LintedFile& f : files)
    for (const ir::Diagnostic& d : f.result.diagnostics) {
      json physical = {{"artifactLocation", {{"uri", uriPath(f.file.path)}}}};
      if (d.loc.line) physical["region"] = {{"startLine", d.loc.line}, {"startColumn", d.loc.column}};
      results.push_back({{"ruleId", d.code.empty() ? "matc" : d.code},
                         {"level", severity(d)},
                         {"message", {{"text", d.message}}},
                         {"locations", json::array({{{"physicalLocation", physical}}})}});
    }
  json run = {{"tool", {{"driver", {{"name", "matc lint"}, {"version", toolVersion}, {"rules", rules}}}}},
              {"columnKind", "unicodeCodePoints"},
              {"results", results}};
  json root = {
      {"$schema", "https://json.schemastore.org/sarif-2.1.0.json"}, {"version", "2.1.0"}, {"runs", json::array({run})}};
  return root.dump(2) + "\n";
}

}  // namespace facet::lint
