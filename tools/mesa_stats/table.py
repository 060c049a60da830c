#!/usr/bin/env python3
"""Prints the tables of docs/mesa-statistics.md from the calibration data.

  tools/mesa_stats/table.py tools/calibration/mesa-stats.json        # every example variant
  tools/mesa_stats/table.py tools/calibration/mesa-single-ops.json   # one operation each
"""

import json
import sys


def single_ops(data):
    # Valhall pipes back to operation counts: Mesa divides FMA/CVT ops by 64 and SFU ops by 16.
    print("| op | G57 mediump: FMA / CVT slots, SFU ops | G57 highp | G52 arith cycles mediump / highp "
          "| A630 mediump: non-nop instr., cat4 | A630 highp |")
    print("|---|---|---|---|---|---|")
    g = data["gpus"]
    for op in sorted(g["mali-g57"]["mediump"]):
        cells = []
        for p in ("mediump", "highp"):
            m = g["mali-g57"][p][op]
            cells.append("%.2f / %.2f, %.2f" % (m["fma"] * 64, m["cvt"] * 64, m["sfu"] * 16))
        cells.append("%.3f / %.3f" % (g["mali-g52"]["mediump"][op]["arith"], g["mali-g52"]["highp"][op]["arith"]))
        for p in ("mediump", "highp"):
            a = g["adreno-630"][p][op]
            cells.append("%.2f, %.2f" % (a["non-nops"], a["cat4"]))
        print("| %s | %s |" % (op, " | ".join(cells)))


def main(argv):
    with open(argv[0]) as f:
        data = json.load(f)
    if "variants" not in data:
        single_ops(data)
        return 0
    print("| variant | G52 cycles | G57 cycles | G57 fma / cvt / sfu / t | G57 inst | A630 inst (non-nop) "
          "| A630 cat4 | A630 regs / waves | SPIR-V scalar / transc / div / tex |")
    print("|---|---:|---:|---|---:|---:|---:|---|---|")
    for name in sorted(data["variants"]):
        v = data["variants"][name]
        g52, g57, a6 = (v["gpus"][g]["fragment"] for g in ("mali-g52", "mali-g57", "adreno-630"))
        p, c = g57["pipes"], v["spirv_cost"]["fragment"]
        print("| %s | %.2f | %.2f | %.2f / %.2f / %.2f / %.2f | %d | %d (%d) | %d | %d / %d | %d / %d / %d / %d |" % (
            name, g52["cycles"], g57["cycles"], p["fma"], p["cvt"], p["sfu"], p["t"], g57["instructions"],
            a6["instructions"], a6["raw"]["non-nops"], a6["categories"]["cat4"], a6["registers"]["full"],
            a6["waves"], c["scalar_alu"], c["transcendental"], c["divisions"], c["textures"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
