// ibl/env_brdf_fits.h
// Analytic stand-ins for the DFG table (dfg_lut.h) on tiers that would rather spend ALU than a
// texture fetch (Zioma 2015: mind the ALU:TEX ratio). Both return the split-sum specular factor
// for a white environment in Karis's form  envBrdf = f0 · A + B  (f90 = 1), r = perceptual
// roughness, n·v in [0, 1]. docs/ibl.md has their measured error against the table.
#pragma once

namespace facet::ibl {

struct EnvBrdfTerms {
  double f0Scale = 0;  // A
  double bias = 0;     // B

  double apply(double f0) const { return f0 * f0Scale + bias; }
};

/// Karis 2014, "Physically Based Shading on Mobile" (Unreal Engine blog), after Lazarov 2013
/// ("Getting More Physical in Call of Duty: Black Ops II"): a fit in r and n·v with one exp2,
///   k = r · (−1, −0.0275, −0.572, 0.022) + (1, 0.0425, 1.04, −0.04)
///   s = min(k.x², 2^(−9.28 n·v)) · k.x + k.y
///   A = −1.04 s + k.z,   B = 1.04 s + k.w
/// Fitted to UE4's own table, whose visibility (separable Schlick–Smith, k = α/2) differs from
/// Facet's height-correlated Smith, so its error below mixes fit error with that model difference.
EnvBrdfTerms envBrdfKaris(double NoV, double perceptualRoughness);

/// Zioma, "Optimizing PBR", SIGGRAPH 2015 ("Environment BRDF"): Karis's curve refitted without
/// the exponent, as on the slide
///   envBrdf = (1 − max(r, n·v))³ + f0,   i.e. A = 1, B = (1 − max(r, n·v))³
/// The slide has no clamp: for f0 = 1 it exceeds 1 everywhere except n·v = 1 or r = 1.
EnvBrdfTerms envBrdfZioma(double NoV, double perceptualRoughness);

/// The slide's form with the sum saturated (min(…, 1)), which a shader gets for free with
/// saturate(); Facet's bounded variant, measured beside the slide's in docs/ibl.md.
double envBrdfZiomaSaturated(double f0, double NoV, double perceptualRoughness);

}  // namespace facet::ibl
