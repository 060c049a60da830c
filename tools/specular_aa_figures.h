// tools/specular_aa_figures.h — the specular anti-aliasing figures of docs/material-models.md
// ("Specular anti-aliasing"), printed by tools/measure_specular_aa.cpp and bounded by
// tests/runtime/test_specular_aa.cpp: a scene (a dense normal-mapped floor whose image is all
// specular) rendered with 1 sample per pixel against a reference of the same scene with 16 samples
// (4×4, box-filtered; supersample.h) and without specular anti-aliasing:
//   specular ratio   the image's summed HDR values over the reference's, each averaged over the
//                    sweep below (what the filtering must keep: it spreads a highlight, it should
//                    not add or remove light; one frame of a floor that aliases is off by its noise,
//                    ±15 %, which the sweep's mean averages out to its bias);
//   PSNR             of the 8-bit output against the reference's, averaged in linear light (each
//                    sample tone-mapped, then averaged: what a 4× larger screen shows);
//   PSNR of HDR      the same against the reference resolved before tone mapping (the samples'
//                    HDR mean, then tone-mapped): what a filter that spreads HDR light can match.
//                    The two differ where samples saturate: a sun's glint is 1 in 8 bits at any
//                    HDR value above the tone curve's knee;
//   flicker          over a sweep of 16 camera positions 1/16 pixel apart: the mean |frame-to-frame
//                    difference| (8-bit steps), and the mean |that difference − the reference's|,
//                    value by value (the part of the change the motion does not explain).
#pragma once

#include <string>
#include <vector>

#include "facet/eval/metrics.h"
#include "supersample.h"

namespace facet::supersample {

struct Reference {
  double hdrSum = 0;                        // summed RGB of the 4×-scale images, / 16, the sweep's mean
  std::vector<uint8_t> image;               // the 16 samples averaged in linear light
  std::vector<uint8_t> resolved;            // the 16 samples' HDR mean, tone-mapped
  std::vector<std::vector<uint8_t>> sweep;  // the same, at each camera position
};

struct SpecularAaFigures {
  double specularRatio = 0;
  double psnr = 0;
  double psnrHdr = 0;
  double flicker = 0;
  double flickerBeyondReference = 0;
  std::vector<uint8_t> firstFrame;  // the 8-bit image at the sweep's first position
};

inline constexpr int kSweepSteps = 16;

inline double hdrSum(const runtime::FrameResult& r) {
  double sum = 0;
  for (size_t i = 0; i < r.hdr.size(); ++i)
    if (i % 4 != 3) sum += double(r.hdr[i]);
  return sum;
}

inline bool measureReference(runtime::RenderBackend& backend, const runtime::Scene& scene, const std::string& packages,
                             Reference* out, std::string* error) {
  for (int step = 0; step < kSweepSteps; ++step) {
    runtime::FrameResult r;
    if (!render(backend, scene, 4, double(step) / kSweepSteps, packages, &r, error)) return false;
    out->sweep.push_back(downsampleLdr(r, 4));
    out->hdrSum += hdrSum(r) / 16.0 / kSweepSteps;
    if (step == 0) {
      out->image = out->sweep.back();
      out->resolved = resolveThenToneMap(r, 4);
    }
  }
  return true;
}

inline bool measureOneSample(runtime::RenderBackend& backend, const runtime::Scene& scene, const std::string& packages,
                             const Reference& reference, SpecularAaFigures* out, std::string* error) {
  std::vector<std::vector<uint8_t>> frames;
  for (int step = 0; step < kSweepSteps; ++step) {
    runtime::FrameResult r;
    if (!render(backend, scene, 1, double(step) / kSweepSteps, packages, &r, error)) return false;
    out->specularRatio += hdrSum(r) / reference.hdrSum / kSweepSteps;
    if (step == 0) {
      out->psnr = eval::psnr8(r.ldr, reference.image);
      out->psnrHdr = eval::psnr8(r.ldr, reference.resolved);
    }
    frames.push_back(std::move(r.ldr));
  }
  out->firstFrame = frames.front();
  flicker(frames, reference.sweep, &out->flicker, &out->flickerBeyondReference);
  return true;
}

}  // namespace facet::supersample
