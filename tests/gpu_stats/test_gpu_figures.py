#!/usr/bin/env python3
"""`matc lint --gpu` on Mesa's real compilers: its per-GPU figures are those mesa_compile.py
prints for the same package's GLSL ES. Runs only where scripts/build-mesa-shader-compilers.sh
has built the compilers: elsewhere it prints why and exits 77 (ctest: "Skipped", never a pass).

  test_gpu_figures.py build/test/matc/matc"""

import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "tools", "mesa_stats"))
import mesa_compile  # noqa: E402

GPUS = ["mali-g57", "adreno-630"]
MATERIAL = os.path.join(ROOT, "examples", "materials", "red_plastic.mat")
MATC = None


class LintGpuFigures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.TemporaryDirectory(prefix="facet-gpu-figures-")
        pkg = os.path.join(cls.work.name, "red_plastic.matpkg")
        subprocess.run([MATC, "compile", MATERIAL, "-o", pkg, "--tiers", "high"], check=True, stdout=subprocess.DEVNULL)
        lint = subprocess.run([MATC, "lint", MATERIAL, "--tiers", "high", "--gpu", ",".join(GPUS), "--format", "json"],
                              check=True, capture_output=True, text=True)
        cls.lint = {g["gpu"]: g for g in json.loads(lint.stdout)["files"][0]["gpus"]}
        direct = subprocess.run([sys.executable, mesa_compile.__file__, "--gpu", ",".join(GPUS), "--matc", MATC,
                                 "--package", pkg], check=True, capture_output=True, text=True)
        cls.direct = json.loads(direct.stdout)["gpus"]

    @classmethod
    def tearDownClass(cls):
        cls.work.cleanup()

    def test_every_gpu_was_measured(self):
        for gpu in GPUS:
            self.assertNotIn("unavailable", self.lint[gpu], gpu)
            self.assertEqual(self.lint[gpu]["renderer"], self.direct[gpu]["renderer"])
            self.assertEqual(sorted(self.lint[gpu]["shaders"]), sorted(self.direct[gpu]["shaders"]))

    def test_lint_reports_what_the_tool_measures(self):
        for gpu in GPUS:
            for variant, stages in self.direct[gpu]["shaders"].items():
                for stage, stats in stages.items():
                    if stage == "other":
                        continue
                    got = self.lint[gpu]["shaders"][variant][stage]
                    self.assertEqual(got["instructions"], stats["instructions"], (gpu, variant, stage))
                    self.assertEqual(got.get("cycles"), stats["cycles"], (gpu, variant, stage))

    def test_mali_fragment_has_cycles_and_a_bound_adreno_has_waves(self):
        frag = self.lint["mali-g57"]["shaders"]["high.dir1"]["fragment"]
        self.assertGreater(frag["cycles"], 0)
        self.assertIn(frag["bound"], ("fma", "cvt", "sfu", "v", "t", "ls"))
        self.assertGreater(self.lint["adreno-630"]["shaders"]["high.dir1"]["fragment"]["waves"], 0)

    def test_text_report_says_which_figures_it_used(self):
        text = subprocess.run([MATC, "lint", MATERIAL, "--tiers", "high", "--gpu", "mali-g57"],
                              check=True, capture_output=True, text=True).stdout
        self.assertIn("per-GPU figures: Mesa 22.3's compilers on drm-shim (mali-g57)", text)
        self.assertIn("high.dir1          fragment", text)


if __name__ == "__main__":
    MATC = os.path.abspath(sys.argv.pop(1))
    reason = mesa_compile.missing_reason(mesa_compile.default_prefix(), GPUS)
    if reason:
        print("SKIPPED, nothing tested: %s" % reason)
        sys.exit(77)
    unittest.main(verbosity=2)
