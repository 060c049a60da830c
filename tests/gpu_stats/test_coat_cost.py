#!/usr/bin/env python3
"""The clear coat's cost goal on Mesa's real Mali-G57 compiler (docs/material-models.md, "Cost and
error"): in high, the coat adds to car_paint's sun + IBL fragment stage (high.dir1) at most what
Filament 1.9.25's clear coat adds to its lit shader, 0.55 cycles. Measured as the material against
a copy with `tier high { clear_coat = none }`, the same GLSL ES the packages ship. Runs only where
scripts/build-mesa-shader-compilers.sh has built the compilers: elsewhere it prints why and exits
77 (ctest: "Skipped", never a pass).

  test_coat_cost.py build/test/matc/matc"""

import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools", "mesa_stats"))
import mesa_compile  # noqa: E402
import package_glsl  # noqa: E402

GPU = "mali-g57"
MATERIAL = os.path.join(ROOT, "examples", "materials", "car_paint.mat")
GOAL = 0.55  # Filament 1.9.25's lit + clear coat against its lit (docs/material-models.md)
MATC = None


def fragment_cycles(work, name, source):
    mat = os.path.join(work, name + ".mat")
    with open(mat, "w") as f:
        f.write(source)
    pkg = os.path.join(work, name + ".matpkg")
    subprocess.run([MATC, "compile", mat, "-o", pkg, "--tiers", "high"], check=True, stdout=subprocess.DEVNULL)
    pairs, _ = package_glsl.package_pairs(MATC, pkg, os.path.join(work, name), ["high.dir1"])
    result = mesa_compile.collect(mesa_compile.default_prefix(), [GPU], pairs)
    return result[GPU]["shaders"]["high.dir1"]["fragment"]["cycles"]


class ClearCoatCost(unittest.TestCase):
    def test_high_coat_adds_at_most_filaments_increment(self):
        with open(MATERIAL) as f:
            coated = f.read()
        header = "material car_paint {"
        self.assertIn(header, coated)
        bare = coated.replace(header, header + "\n    tier high { clear_coat = none }", 1)
        with tempfile.TemporaryDirectory(prefix="facet-coat-cost-") as work:
            with_coat = fragment_cycles(work, "coated", coated)
            without = fragment_cycles(work, "bare", bare)
        print("car_paint high.dir1 on %s: %.4f cycles with the coat, %.4f without (+%.4f, goal %.2f)"
              % (GPU, with_coat, without, with_coat - without, GOAL))
        self.assertGreater(with_coat, without)  # the coat is shaded
        self.assertLessEqual(with_coat - without, GOAL)


if __name__ == "__main__":
    MATC = os.path.abspath(sys.argv.pop(1))
    reason = mesa_compile.missing_reason(mesa_compile.default_prefix(), [GPU])
    if reason:
        print("SKIPPED, nothing tested: %s" % reason)
        sys.exit(77)
    unittest.main(verbosity=2)
