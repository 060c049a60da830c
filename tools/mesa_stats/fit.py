#!/usr/bin/env python3
"""Fits per-class weights of Facet's static SPIR-V cost counts to the fragment cycles (Mali) and
instructions (Adreno) measured by Mesa's compilers (tools/calibration/mesa-stats.json), and reports the error before and after.

  tools/mesa_stats/fit.py tools/calibration/mesa-stats.json [-o tools/calibration/mesa-fit.json]

Model: measure ≈ Σ_k w_k · count_k over the StageCost classes of spirv_cost.h (scalar ALU ops
split into mediump and highp, transcendentals, divisions, texture samples, varying components),
w_k ≥ 0 (non-negative least squares: every subset of classes solved by least squares, the best
all-non-negative one kept; exact for six classes). "Before" is the a-priori model from DESIGN.md's facts ("Facts measured on mobile GPU compilers") and
Mesa's Valhall rates: max((scalar + 4·transc + 4·div) / 64, tex / 4, varyings / 16).
Cross-validation: fit on three materials, predict the fourth, for each material in turn.

Standard library only: six unknowns need no numpy, and the calibration test then runs on every
Python CMake finds.
"""

import argparse
import itertools
import json
import math
import sys

# The counts of spirv_cost.h, scalar ALU ops split by precision: mediump work packs two fp16 lanes
# per slot on Valhall. StageCost has the mediump share of ALU + transcendental ops only
# (relaxedPercent, printed rounded to 1 %), so the split applies that share to the scalar count.
CLASSES = ["scalarMediump", "scalarHighp", "transcendentalOps", "divisions", "textureSamples", "varyingComponents"]


def features(cost):
    relaxed = cost["relaxedPercent"] / 100.0
    derived = {"scalarMediump": cost["scalarAluOps"] * relaxed, "scalarHighp": cost["scalarAluOps"] * (1 - relaxed)}
    return [derived[k] if k in derived else cost[k] for k in CLASSES]
# What is fitted per GPU: Mali's cycle bound; ir3 prints no cycles, so its non-nop instruction
# count (issue slots of one wave) stands in.
TARGETS = {"mali-g57": "cycles", "mali-g52": "cycles", "adreno-630": "non-nops"}
# The a-priori model is Valhall's (Mesa's G78 rates); it says nothing about Bifrost's or ir3's scale.
A_PRIORI = {"mali-g57"}


def a_priori_cycles(c):
    arith = (c["scalarAluOps"] + 4 * c["transcendentalOps"] + 4 * c["divisions"]) / 64.0
    return max(arith, c["textureSamples"] / 4.0, c["varyingComponents"] / 16.0)


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
    """Non-negative least squares by enumerating the classes kept (2^6 small systems)."""
    n = len(rows[0])
    best, best_err = [0.0] * n, sum(t * t for t in y)
    for size in range(1, n + 1):
        for keep in itertools.combinations(range(n), size):
            w = least_squares([[r[i] for i in keep] for r in rows], y)
            if w is None or any(v < 0 for v in w):
                continue
            full = [0.0] * n
            for i, v in zip(keep, w):
                full[i] = v
            err = sum((predict(full, r) - t) ** 2 for r, t in zip(rows, y))
            if err < best_err - 1e-15:
                best, best_err = full, err
    return best


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
    """(material, variant, counts row, measured fragment cycles) for every variant."""
    out = []
    for name in sorted(data["variants"]):
        v = data["variants"][name]
        frag = v["gpus"][gpu]["fragment"]
        cost = v["spirv_cost"]["fragment"]
        measured = frag["cycles"] if TARGETS[gpu] == "cycles" else frag["raw"][TARGETS[gpu]]
        out.append((name.split("/")[0], name, features(cost), measured, cost))
    return out


def fit_gpu(data, gpu):
    s = samples(data, gpu)
    rows, y = [r for _, _, r, _, _ in s], [t for _, _, _, t, _ in s]
    w = nnls(rows, y)
    fitted = [predict(w, r) for r in rows]
    before = [a_priori_cycles(c) for _, _, _, _, c in s] if gpu in A_PRIORI else None
    cv = []
    for material in sorted({m for m, _, _, _, _ in s}):
        train = [(r, t) for m, _, r, t, _ in s if m != material]
        wm = nnls([r for r, _ in train], [t for _, t in train])
        cv += [(predict(wm, r), t) for m, _, r, t, _ in s if m == material]
    # matc's own mobile cost model, when the matc that collected the data printed its estimate
    # (a `cycles` column in `matc info`): its error against the same measure, as it stands.
    model = [c.get("mobileCostCycles") for _, _, _, _, c in s]
    matc_model = errors(model, y) if gpu in A_PRIORI and None not in model else None
    return {
        "measure": "fragment " + TARGETS[gpu],
        "matc_model": matc_model,
        "weights": {k: round(v, 9) for k, v in zip(CLASSES, w)},
        "samples": len(y),
        "before": errors(before, y) if before else None,
        "after": errors(fitted, y),
        "cross_validated": errors([p for p, _ in cv], [t for _, t in cv]),
        "per_variant": {n: {"measured": t, "before": round(before[i], 6) if before else None,
                            "after": round(fitted[i], 6)}
                        for i, (_, n, _, t, _) in enumerate(s)},
    }


def fit(data):
    return {gpu: fit_gpu(data, gpu) for gpu in sorted(TARGETS) if gpu in data["gpus"]}


def rounded(obj):
    if isinstance(obj, float):
        return round(obj, 6)
    if isinstance(obj, dict):
        return {k: rounded(v) for k, v in obj.items()}
    return obj


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("stats")
    ap.add_argument("-o", "--output")
    args = ap.parse_args(argv)
    with open(args.stats) as f:
        result = rounded(fit(json.load(f)))
    for gpu, r in result.items():
        unit = TARGETS[gpu]
        print("%s %s, %d variants" % (gpu, r["measure"], r["samples"]))
        print("  weights (%s per op): " % unit + ", ".join("%s %.5f" % kv for kv in r["weights"].items()))
        for label in ("matc_model", "before", "after", "cross_validated"):
            e = r[label]
            if e is None:
                continue
            print("  %-16s rms %.3f %s, mean |rel| %5.1f %%, max |rel| %5.1f %%"
                  % (label, e["rms"], unit, 100 * e["mean_abs_relative"], 100 * e["max_abs_relative"]))
    if args.output:
        with open(args.output, "w") as f:
            json.dump({"generated_by": "tools/mesa_stats/fit.py tools/calibration/mesa-stats.json "
                                       "-o tools/calibration/mesa-fit.json",
                       "model": "fragment measure = sum of weight x SPIR-V cost count (spirv_cost.h), weights >= 0",
                       "fits": result}, f, indent=1, sort_keys=True)
            f.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
