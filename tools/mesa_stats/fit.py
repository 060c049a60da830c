#!/usr/bin/env python3
"""Fits the weights of the mobile cost model's operation classes (countOpClasses of
compiler/mobile_cost.h) to the fragment cycles (Mali) and instructions (Adreno) measured by Mesa's
compilers, over the example materials' variants (tools/calibration/mesa-stats.json) and the
single-operation shaders (tools/calibration/mesa-single-ops.json), and reports the error before
and after, and cross-validated.

  tools/mesa_stats/fit.py -o tools/calibration/mesa-fit.json --cpp compiler/src/mesa_calibration.cpp

Model: measure ≈ Σ_k w_k · count_k, w_k ≥ 0 (non-negative least squares, Lawson–Hanson), over
the classes a single-operation shader pins (FEATURES: each has an op whose SPIR-V counts are that
class alone, or that class plus FMA work). Rows:
- a variant: its fragment counts against its fragment measure, the error relative to the measure;
- a single operation (per scalar component, both precisions): its counts against the pipe that
  bounds every example variant (G57 FMA, G52 arithmetic; Adreno non-nop instructions), scaled
  to units of one highp FMA-pipe op and weighted by PIN_WEIGHT, so that a class the examples
  barely use (or never use: pow, tan, atan) still gets its measured weight.
"Before" is matc's mobile cost model as it stands (its `cycles` figure, G57 only).
Cross-validation: fit on the single operations and three materials, predict the fourth's
variants, for each material in turn.

Standard library only: a dozen unknowns need no numpy, and the calibration test then runs on
every Python CMake finds.
"""

import argparse
import json
import math
import os
import sys

CALIBRATION = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "calibration")

# The classes of mobile_cost.h the fit weighs, FMA work split by precision (Valhall packs two fp16
# lanes per FMA slot). Not here: modifiers and fused adds (free by construction), and classes no
# single-operation shader isolates (hyperbolic, integer division, derivatives; the examples use none).
FEATURES = ["fma_mediump", "fma_highp", "convert", "sfu", "exp_log", "sqrt", "pow", "sin_cos", "tan",
            "inverse_trig", "atan2", "division", "texture_sample"]
# What is fitted per GPU, for a variant and for a single operation: Mali's cycle bound (every
# example variant is bound by the FMA pipe on G57 and the arithmetic pipe on G52, so a single
# operation is measured on that pipe); ir3 prints no cycles, so its non-nop instruction count
# (issue slots of one wave) stands in.
TARGETS = {"mali-g57": ("cycles", "fma"), "mali-g52": ("cycles", "arith"), "adreno-630": ("non-nops", "non-nops")}
# The relative weight of a single-operation row (in highp FMA ops) against a variant row (in
# relative error): one FMA op of error on a pinned op counts as PIN_WEIGHT relative error on a
# variant. Chosen by cross-validation over 0.001–1 (docs/mesa-statistics.md).
PIN_WEIGHT = 0.01
# matc's own model is Valhall's (Mesa's G78 rates); it says nothing about Bifrost's or ir3's scale.
A_PRIORI = {"mali-g57"}


def features(counts):
    derived = {"fma_mediump": counts["fma_relaxed"], "fma_highp": counts["fma"] - counts["fma_relaxed"]}
    return [derived[k] if k in derived else counts[k] for k in FEATURES]


def solve(a, b):
    """Solves the square system a·x = b by Gaussian elimination with partial pivoting; None when
    singular."""
    n = len(b)
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(m[r][col]))
        if abs(m[pivot][col]) < 1e-12:
            return None
        m[col], m[pivot] = m[pivot], m[col]
        for r in range(n):
            if r != col:
                f = m[r][col] / m[col][col]
                for k in range(col, n + 1):
                    m[r][k] -= f * m[col][k]
    return [m[i][n] / m[i][i] for i in range(n)]


def least_squares(rows, y):
    """argmin ||rows·w − y|| through the normal equations (a few well-scaled unknowns)."""
    n = len(rows[0])
    ata = [[sum(r[i] * r[j] for r in rows) for j in range(n)] for i in range(n)]
    aty = [sum(r[i] * t for r, t in zip(rows, y)) for i in range(n)]
    return solve(ata, aty)


def nnls(rows, y):
    """Lawson–Hanson non-negative least squares: min ||rows·w − y||, w ≥ 0."""
    n = len(rows[0])
    w, passive = [0.0] * n, []

    def gradient(w):
        r = [t - predict(w, row) for row, t in zip(rows, y)]
        return [sum(row[i] * ri for row, ri in zip(rows, r)) for i in range(n)]

    for _ in range(10 * n):
        g = gradient(w)
        free = [i for i in range(n) if i not in passive and g[i] > 1e-10]
        if not free:
            break
        passive.append(max(free, key=lambda i: g[i]))
        while True:
            z = [0.0] * n
            sol = least_squares([[row[i] for i in passive] for row in rows], y)
            if sol is None:
                passive.pop()
                break
            for i, v in zip(passive, sol):
                z[i] = v
            if all(z[i] > 0 for i in passive):
                w = z
                break
            alpha = min(w[i] / (w[i] - z[i]) for i in passive if z[i] <= 0)
            w = [w[i] + alpha * (z[i] - w[i]) for i in range(n)]
            passive = [i for i in passive if w[i] > 1e-12]
    return w


def predict(w, row):
    return sum(a * b for a, b in zip(w, row))


def errors(pred, y):
    rel = [abs(p - t) / t for p, t in zip(pred, y)]
    return {
        "rms": math.sqrt(sum((p - t) ** 2 for p, t in zip(pred, y)) / len(y)),
        "mean_abs_relative": sum(rel) / len(rel),
        "max_abs_relative": max(rel),
    }


def samples(data, gpu):
    """(material, variant, feature row, measured fragment figure, matc's cycles) per variant."""
    out = []
    for name in sorted(data["variants"]):
        v = data["variants"][name]
        frag = v["gpus"][gpu]["fragment"]
        measure = TARGETS[gpu][0]
        measured = frag["cycles"] if measure == "cycles" else frag["raw"][measure]
        out.append((name.split("/")[0], name, features(v["op_counts"]["fragment"]), measured,
                    v["spirv_cost"]["fragment"].get("cycles")))
    return out


def pin_rows(single_ops, gpu):
    """Single-operation rows, scaled to units of one highp FMA-pipe op and by PIN_WEIGHT."""
    pipe = TARGETS[gpu][1]
    unit = single_ops["gpus"][gpu]["highp"]["mul"][pipe]
    rows = []
    for precision in ("mediump", "highp"):
        for op in sorted(single_ops["op_counts"][precision]):
            f = features(single_ops["op_counts"][precision][op])
            t = single_ops["gpus"][gpu][precision][op][pipe]
            rows.append(([x / unit * PIN_WEIGHT for x in f], t / unit * PIN_WEIGHT))
    return rows


def weighted_fit(variant_rows, pins):
    rows = [[x / t for x in r] for r, t in variant_rows] + [r for r, _ in pins]
    y = [1.0] * len(variant_rows) + [t for _, t in pins]
    return nnls(rows, y)


def fit_gpu(data, single_ops, gpu):
    s = samples(data, gpu)
    pins = pin_rows(single_ops, gpu)
    y = [t for _, _, _, t, _ in s]
    w = weighted_fit([(r, t) for _, _, r, t, _ in s], pins)
    fitted = [predict(w, r) for _, _, r, _, _ in s]
    cv = []
    for material in sorted({m for m, _, _, _, _ in s}):
        wm = weighted_fit([(r, t) for m, _, r, t, _ in s if m != material], pins)
        cv += [(predict(wm, r), t) for m, _, r, t, _ in s if m == material]
    before = [c for _, _, _, _, c in s]
    before = before if gpu in A_PRIORI and None not in before else None
    return {
        "measure": "fragment " + TARGETS[gpu][0],
        "single_op_measure": TARGETS[gpu][1],
        "weights": {k: round(v, 9) for k, v in zip(FEATURES, w)},
        "samples": len(y),
        "single_op_rows": len(pins),
        "before": errors(before, y) if before else None,
        "after": errors(fitted, y),
        "cross_validated": errors([p for p, _ in cv], [t for _, t in cv]),
        "per_variant": {n: {"measured": t, "before": before[i] if before else None, "after": round(fitted[i], 6)}
                        for i, (_, n, _, t, _) in enumerate(s)},
    }


def fit(data, single_ops):
    return {gpu: fit_gpu(data, single_ops, gpu) for gpu in sorted(TARGETS) if gpu in data["gpus"]}


def rounded(obj):
    if isinstance(obj, float):
        return round(obj, 6)
    if isinstance(obj, dict):
        return {k: rounded(v) for k, v in obj.items()}
    return obj


CPP_FIELDS = [("after", "mean_abs_relative"), ("after", "max_abs_relative"),
              ("cross_validated", "mean_abs_relative"), ("cross_validated", "max_abs_relative")]


def cpp_source(result):
    """compiler/src/mesa_calibration.cpp: the fitted weights for compiler::gpuCalibrations()."""
    lines = ["// Generated by tools/mesa_stats/fit.py -o tools/calibration/mesa-fit.json --cpp compiler/src/mesa_calibration.cpp",
             "// from tools/calibration/mesa-stats.json and mesa-single-ops.json (docs/mesa-statistics.md,",
             "// \"Calibration\"); do not edit. Weights in the order of CalibratedClass: " + ", ".join(FEATURES) + ".",
             '#include "facet/compiler/mobile_cost.h"', "", "namespace facet::compiler {", "",
             "const std::vector<GpuCalibration>& gpuCalibrations() {",
             "  static const std::vector<GpuCalibration> calibrations = {"]
    for gpu, r in result.items():
        weights = ", ".join(repr(float(r["weights"][k])) for k in FEATURES)
        errors = ", ".join(repr(float(r[a][b])) for a, b in CPP_FIELDS)
        lines.append('      {"%s", "%s", {%s}, %s},' % (gpu, r["measure"], weights, errors))
    lines += ["  };", "  return calibrations;", "}", "", "}  // namespace facet::compiler", ""]
    return "\n".join(lines)


def load(name):
    with open(os.path.join(CALIBRATION, name)) as f:
        return json.load(f)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("-o", "--output")
    ap.add_argument("--cpp", help="also write the weights as C++ (compiler/src/mesa_calibration.cpp)")
    args = ap.parse_args(argv)
    result = rounded(fit(load("mesa-stats.json"), load("mesa-single-ops.json")))
    for gpu, r in result.items():
        unit = TARGETS[gpu][0]
        print("%s %s, %d variants + %d single-op rows" % (gpu, r["measure"], r["samples"], r["single_op_rows"]))
        print("  weights (%s per op): " % unit + ", ".join("%s %.5f" % kv for kv in r["weights"].items()))
        for label in ("before", "after", "cross_validated"):
            e = r[label]
            if e is None:
                continue
            print("  %-16s rms %.3f %s, mean |rel| %5.1f %%, max |rel| %5.1f %%"
                  % (label, e["rms"], unit, 100 * e["mean_abs_relative"], 100 * e["max_abs_relative"]))
    if args.output:
        with open(args.output, "w") as f:
            json.dump({"generated_by": "tools/mesa_stats/fit.py -o tools/calibration/mesa-fit.json",
                       "model": "fragment measure = sum of weight x op-class count (mobile_cost.h countOpClasses), "
                                "weights >= 0, fitted on the example variants and the single operations",
                       "fits": result}, f, indent=1, sort_keys=True)
            f.write("\n")
    if args.cpp:
        with open(args.cpp, "w") as f:
            f.write(cpp_source(result))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
