#include "sweep_support.h"

#include <cmath>

#include "facet/compiler/assemble.h"
#include "facet/compiler/lower_relaxed_to_quantized.h"
#include "facet/compiler/specular_lut.h"
#include "facet/ibl/dfg_lut.h"
#include "facet/runtime/environment.h"

namespace facet::eval {

double sweepRoughness(const BrdfSweepDomain& domain, int row) {
  return domain.roughnesses == 1
             ? 1.0
             : kMinPerceptualRoughness + (1.0 - kMinPerceptualRoughness) * row / (domain.roughnesses - 1);
}

std::string axisValue(const char* axisName, const permutations::TierConfig& config) {
  for (const Axis& axis : axes())
    if (std::string(axis.name) == axisName) return axis.get(config);
  return "";
}

std::string precisionName(permutations::PrecisionPolicy precision) {
  return precision == permutations::PrecisionPolicy::Highp ? "highp (fp32)" : "mediump (fp16 emulated)";
}

std::string setPrecision(GpuEvalRequest* request, permutations::PrecisionPolicy precision) {
  request->highpInputs = true;
  if (precision == permutations::PrecisionPolicy::Highp) {
    request->precision = FloatPrecision::Highp;
    request->transformSpirv = nullptr;
    return "#define FACET_PRECISION_HIGHP 1\n";
  }
  request->precision = FloatPrecision::Mediump;
  request->transformSpirv = [](std::vector<uint32_t>* words, std::string* e) {
    compiler::QuantizeCounts counts;
    return compiler::lowerRelaxedToQuantized(words, &counts, e);
  };
  return "";
}

bool setSpecularLobe(GpuEvalRequest* request, permutations::SpecularModel model,
                     permutations::PrecisionPolicy precision, GpuR8Texture* lut, std::string* error) {
  std::string lobe;
  if (!compiler::specularLobeSource(model, &lobe, error)) return false;
  std::string defines = setPrecision(request, precision);
  defines += std::string("#define ") + compiler::kSpecularLutSamplerName + " lut\n";
  request->chunks = {defines, lobe};
  if (model == permutations::SpecularModel::Lut) {
    compiler::SpecularLut table = compiler::generateSpecularLut();
    *lut = {table.width, table.height, std::move(table.texels)};
    request->lut = lut;
  }
  return true;
}

double specularLobeColor(permutations::SpecularModel model, double NoV, double perceptualRoughness, double f0) {
  if (model != permutations::SpecularModel::Lut) return f0;
  return ibl::specularEnvironmentBrdf(runtime::dfgTable().sampleBilinear(NoV, perceptualRoughness), f0);
}

void RowErrors::add(size_t row, double value, double expected, double NoV, bool beyondHalf, BrdfSweepRow* out) {
  if (!std::isfinite(value)) {
    ++out->nonFinite;
    return;
  }
  if (beyondHalf) {
    ++out->beyondHalf;
    return;
  }
  const double weights[2] = {1.0, NoV};
  for (size_t w = 0; w < 2; ++w) {
    error_[row][w] += weights[w] * (value - expected) * (value - expected);
    reference_[row][w] += weights[w] * expected * expected;
  }
}

void RowErrors::finish(BrdfSweepRow* out) const {
  const size_t rowCount = error_.size();
  for (size_t k = 0; k < rowCount; ++k) {
    auto rmse = [&](size_t w) { return reference_[k][w] > 0 ? std::sqrt(error_[k][w] / reference_[k][w]) : 0.0; };
    out->rowRelativeRmse.push_back(rmse(0));
    out->rowScreenRmse.push_back(rmse(1));
    out->meanRelativeRmse += rmse(0) / double(rowCount);
    out->meanScreenRmse += rmse(1) / double(rowCount);
    if (rmse(0) >= out->worstRelativeRmse) {
      out->worstRelativeRmse = rmse(0);
      out->worstRoughness = out->roughness[k];
    }
  }
}

}  // namespace facet::eval
