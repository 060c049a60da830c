#!/usr/bin/env python3
"""The calibration of docs/mesa-statistics.md: the fit of the cost model's op-class counts to the
fragment figures of Mesa's compilers, recomputed from the committed data
(tools/calibration/mesa-stats.json, mesa-single-ops.json). Needs no Mesa build: it protects the
committed fit (weights and errors as documented) and its quality."""

import json
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools", "mesa_stats"))
import fit  # noqa: E402


def load(name):
    with open(os.path.join(ROOT, "tools", "calibration", name)) as f:
        return json.load(f)


class Calibration(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.data = load("mesa-stats.json")
        cls.fits = fit.rounded(fit.fit(cls.data, load("mesa-single-ops.json")))

    def assertClose(self, got, want, path=""):
        if isinstance(want, dict):
            self.assertEqual(sorted(got), sorted(want), path)
            for k in want:
                self.assertClose(got[k], want[k], path + "/" + k)
        elif isinstance(want, float):
            self.assertAlmostEqual(got, want, delta=2e-6, msg=path)  # both rounded to 6 digits
        else:
            self.assertEqual(got, want, path)

    def test_committed_fit_is_what_the_committed_data_gives(self):
        self.assertClose(self.fits, load("mesa-fit.json")["fits"])

    def test_committed_cpp_weights_are_what_fit_py_generates(self):
        # compiler/src/mesa_calibration.cpp: matc's calibrated estimate (test_mobile_cost checks
        # the C++ features against per_variant).
        with open(os.path.join(ROOT, "compiler", "src", "mesa_calibration.cpp")) as f:
            self.assertEqual(f.read(), fit.cpp_source(self.fits))

    def test_every_example_variant_was_measured_on_every_gpu(self):
        self.assertEqual(len(self.data["variants"]), 32)  # 4 materials x 4 tiers x 2 light counts
        for name, v in self.data["variants"].items():
            self.assertEqual(sorted(v["gpus"]), ["adreno-630", "mali-g52", "mali-g57"], name)
            for gpu, stages in v["gpus"].items():
                self.assertGreater(stages["fragment"]["instructions"], 0, (name, gpu))

    def test_fit_beats_matcs_cost_model_on_valhall(self):
        g57 = self.fits["mali-g57"]
        self.assertIsNotNone(g57["before"], "the data has no spirv_cost cycles: re-collect with a matc whose info --json has them")
        self.assertLess(g57["after"]["rms"], g57["before"]["rms"] / 2)

    def test_every_feature_is_pinned_by_a_single_operation(self):
        # A class no single-operation shader isolates (beside FMA work) would be weighed by the
        # examples alone, which use some classes rarely or never.
        counts = load("mesa-single-ops.json")["op_counts"]
        rows = [fit.features(c) for precision in counts.values() for c in precision.values()]
        fma = {fit.FEATURES.index("fma_mediump"), fit.FEATURES.index("fma_highp")}
        for k, name in enumerate(fit.FEATURES):
            alone = [r for r in rows if r[k] > 0 and all(x == 0 for j, x in enumerate(r) if j != k and j not in fma)]
            self.assertTrue(alone, name)


class SingleOperations(unittest.TestCase):
    """The committed single-operation figures (tools/calibration/mesa-single-ops.json) against
    the facts docs/mesa-statistics.md draws from them."""

    @classmethod
    def setUpClass(cls):
        cls.g57 = load("mesa-single-ops.json")["gpus"]["mali-g57"]

    def sfu_ops(self, precision, op):
        return self.g57[precision][op]["sfu"] * 16  # Mesa: 16 SFU ops per cycle

    def test_valhall_sqrt_and_pow_are_two_sfu_ops_rsq_one(self):
        for p in ("mediump", "highp"):
            self.assertAlmostEqual(self.sfu_ops(p, "sqrt"), 2.0, places=3, msg=p)
            self.assertAlmostEqual(self.sfu_ops(p, "pow"), 2.0, places=3, msg=p)
            self.assertAlmostEqual(self.sfu_ops(p, "inversesqrt"), 1.0, places=3, msg=p)

    def test_valhall_mediump_multiply_is_half_an_fma_slot(self):
        self.assertAlmostEqual(self.g57["mediump"]["mul"]["fma"] * 64, 0.5, places=3)
        self.assertAlmostEqual(self.g57["highp"]["mul"]["fma"] * 64, 1.0, places=3)


if __name__ == "__main__":
    unittest.main(verbosity=2)
