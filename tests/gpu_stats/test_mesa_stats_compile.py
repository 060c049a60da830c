#!/usr/bin/env python3
"""tools/mesa_stats/mesa_compile.py on Mesa's real compilers (drm-shim fake devices).

Runs only where scripts/build-mesa-shader-compilers.sh has built them: elsewhere it prints why
and exits 77, which ctest reports as "Skipped" (never as a pass)."""

import json
import os
import subprocess
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "mesa_stats"))
import mesa_compile  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "mesa_stats")
GPUS = ["mali-g52", "mali-g57", "adreno-630"]
SKIP = 77


def pair(frag):
    return {"name": frag, "vertex": os.path.join(DATA, "pair.vert"), "fragment": os.path.join(DATA, frag)}


class MesaCompilers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # The texture-only shader twice: the second compile must print statistics too (the disk
        # cache is off) and the same ones (the compilers are deterministic).
        pairs = [pair("texture.frag"), pair("pow.frag"), dict(pair("texture.frag"), name="again")]
        cls.result = mesa_compile.collect(mesa_compile.default_prefix(), GPUS, pairs)

    def shaders(self, gpu, name):
        return self.result[gpu]["shaders"][name]

    def test_every_gpu_reports_both_stages(self):
        # Mali splits the vertex shader into position and varying halves (IDVS).
        vertex = {"mali-g52": "vertex_position", "mali-g57": "vertex_position", "adreno-630": "vertex"}
        for gpu in GPUS:
            for name in ("texture.frag", "pow.frag"):
                s = self.shaders(gpu, name)
                self.assertIn(vertex[gpu], s, (gpu, name))
                self.assertGreater(s["fragment"]["instructions"], 0, (gpu, name))

    def test_the_fake_devices_are_the_gpus_asked_for(self):
        self.assertIn("G52", self.result["mali-g52"]["renderer"])
        self.assertIn("G57", self.result["mali-g57"]["renderer"])
        self.assertIn("630", self.result["adreno-630"]["renderer"])

    def test_recompiling_gives_the_same_statistics(self):
        for gpu in GPUS:
            self.assertEqual(self.shaders(gpu, "again"), self.shaders(gpu, "texture.frag"), gpu)

    def test_pow_costs_special_function_work_a_texture_does_not(self):
        tex = self.shaders("mali-g57", "texture.frag")["fragment"]["pipes"]
        pw = self.shaders("mali-g57", "pow.frag")["fragment"]["pipes"]
        self.assertEqual(tex["sfu"], 0.0)
        self.assertGreater(pw["sfu"], 0.0)
        self.assertEqual(tex["t"], pw["t"])
        tex = self.shaders("adreno-630", "texture.frag")["fragment"]["categories"]
        pw = self.shaders("adreno-630", "pow.frag")["fragment"]["categories"]
        self.assertEqual(tex["cat4"], 0)
        self.assertGreater(pw["cat4"], 0)

    def test_more_arithmetic_costs_more_cycles_on_mali(self):
        for gpu in ("mali-g52", "mali-g57"):
            tex = self.shaders(gpu, "texture.frag")["fragment"]
            pw = self.shaders(gpu, "pow.frag")["fragment"]
            self.assertGreater(pw["instructions"], tex["instructions"], gpu)

    def test_disassembly_goes_to_stderr_and_leaves_the_figures(self):
        # --disassembly: each compiler's final code on stderr (Valhall's texture instruction,
        # ir3's program summary line), and the same JSON on stdout.
        run = subprocess.run([sys.executable, mesa_compile.__file__, "--gpu", "mali-g57,adreno-630",
                              "--vertex", os.path.join(DATA, "pair.vert"), "--fragment",
                              os.path.join(DATA, "texture.frag"), "--disassembly"],
                             capture_output=True, text=True, check=True)
        shown = json.loads(run.stdout)["gpus"]
        for gpu in ("mali-g57", "adreno-630"):
            self.assertEqual(shown[gpu]["shaders"]["texture.frag"], self.shaders(gpu, "texture.frag"), gpu)
        mali, adreno = run.stderr.split("=== adreno-630\n")
        self.assertIn("=== mali-g57\n", mali)
        self.assertIn("TEX_SINGLE", mali)
        self.assertIn("; FRAG prog", adreno)


if __name__ == "__main__":
    reason = mesa_compile.missing_reason(mesa_compile.default_prefix(), GPUS)
    if reason:
        print("test_mesa_stats_compile: SKIPPED, nothing tested: %s" % reason)
        sys.exit(SKIP)
    unittest.main(verbosity=2)
