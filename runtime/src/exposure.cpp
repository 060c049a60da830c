#include "facet/runtime/exposure.h"

#include <cmath>

namespace facet::runtime {

double ev100(double aperture, double shutterSeconds, double iso) {
  return std::log2((aperture * aperture) / shutterSeconds * 100.0 / iso);
}

double exposureFromEv100(double ev) { return 1.0 / (1.2 * std::exp2(ev)); }

}  // namespace facet::runtime
