// ibl/ggx_microfacet.h
// The GGX microfacet pieces the IBL integrals share: distribution, height-correlated Smith
// visibility, and the two ways of importance-sampling a microfacet normal. Tangent space: n = +z.
// α = perceptual roughness² (Burley 2012; Filament PBR §4.8), as in chunks/brdf_ggx.glsl.
#pragma once

#include "facet/ibl/hammersley.h"
#include "facet/ibl/vec3.h"

namespace facet::ibl {

/// GGX / Trowbridge–Reitz normal distribution D(h) (Walter et al. 2007).
double distributionGgx(double alpha, double NoH);

/// Height-correlated Smith visibility V = G2 / (4 n·v n·l) (Heitz 2014), Filament's form.
double visibilitySmithGgxCorrelated(double alpha, double NoV, double NoL);

/// Smith masking G1(v) = 2 n·v / (n·v + √(α² + (1 − α²) n·v²)).
double maskingSmithGgx(double alpha, double NoV);

/// A normal h distributed as D(h) n·h (Karis 2013's sampler). Simple, but at grazing view most
/// samples reflect below the horizon or carry huge weights (see dfg_lut.h).
Vec3 sampleGgxNormal(Point2 xi, double alpha);

/// A normal h distributed as the visible normals from v (Heitz 2018, "Sampling the GGX
/// Distribution of Visible Normals", JCGT 7(4)): pdf G1(v) max(v·h, 0) D(h) / n·v. v.z > 0.
Vec3 sampleGgxVisibleNormal(Point2 xi, Vec3 v, double alpha);

/// l = 2 (v·h) h − v.
inline Vec3 reflectAbout(Vec3 v, Vec3 h) { return 2.0 * dot(v, h) * h - v; }

/// An orthonormal frame with n as its third axis, continuous except across n.z = 0's sign
/// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
struct TangentFrame {
  Vec3 t, b, n;
  explicit TangentFrame(Vec3 normal);
  Vec3 toWorld(Vec3 local) const { return local.x * t + local.y * b + local.z * n; }
};

}  // namespace facet::ibl
