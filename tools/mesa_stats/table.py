#!/usr/bin/env python3
"""Prints the fragment-stage table of docs/mesa-statistics.md from the calibration data.

  tools/mesa_stats/table.py tools/calibration/mesa-stats.json
"""

import json
import sys


def main(argv):
    with open(argv[0]) as f:
        data = json.load(f)
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
            a6["waves"], c["scalarAluOps"], c["transcendentalOps"], c["divisions"], c["textureSamples"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
