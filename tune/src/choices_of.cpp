// The tuning file's record of a search (choices.h), apart from the file's reading: matc links that
// (facet_tune_choices) without the search and its renderer.
#include "facet/tune/choices.h"
#include "facet/tune/search.h"

namespace facet::tune {

std::optional<Choices> choicesOf(const TuneReport& report) {
  Choices c;
  c.material = report.material;
  c.gpu = report.gpu;
  c.verticesPerPixel = report.verticesPerPixel;
  for (const TierOutcome& o : report.tiers) {
    if (!o.chosen) return std::nullopt;
    c.tiers.push_back(
        {o.tier, o.chosen->result.configuration.config, o.chosen->cost.total, o.chosen->result.error.psnr});
  }
  return c;
}

}  // namespace facet::tune
