// Physical camera exposure, for pre-exposing lights on the CPU.
//
// EV100 = log2(N² / t × 100 / S)  (aperture N, shutter t seconds, sensitivity S ISO)
// exposure = 1 / (1.2 × 2^EV100): the photometric exposure that maps the luminance a camera
// with these settings saturates at (the 1.2 = 78/(100 × 0.65) saturation-based sensor model,
// ISO 12232) to 1.0.
// Source: Lagarde & de Rousiers, "Moving Frostbite to PBR" (2014), §5.1; Filament §8.1.
#pragma once

namespace facet::runtime {

double ev100(double aperture, double shutterSeconds, double iso);
double exposureFromEv100(double ev100);

}  // namespace facet::runtime
