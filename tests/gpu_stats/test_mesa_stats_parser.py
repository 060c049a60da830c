#!/usr/bin/env python3
"""tools/mesa_stats/shaderdb.py on statistics lines recorded from Mesa 22.3.6's compilers
(tests/data/mesa_stats/, recorded with the command in its README). Needs no Mesa build."""

import json
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "mesa_stats"))
import package_glsl  # noqa: E402
import shaderdb  # noqa: E402

FIXTURES = os.path.join(HERE, "..", "data", "mesa_stats")


def recorded(gpu):
    with open(os.path.join(FIXTURES, gpu + ".txt")) as f:
        return shaderdb.parse_messages(f.readlines())


class MaliStatistics(unittest.TestCase):
    def check_bound_is_busiest_pipe(self, stats):
        for s in stats:
            self.assertAlmostEqual(s["cycles"], max(s["pipes"].values()), places=5, msg=s)

    def test_bifrost_cycles_are_the_busiest_pipe(self):
        stats = recorded("mali-g52")
        self.assertTrue(all(s["family"] == "bifrost" for s in stats))
        self.assertEqual(sorted(stats[0]["pipes"]), ["arith", "ldst", "texture", "vary"])
        self.check_bound_is_busiest_pipe(stats)

    def test_valhall_cycles_are_the_busiest_pipe(self):
        stats = recorded("mali-g57")
        self.assertTrue(all(s["family"] == "valhall" for s in stats))
        self.assertEqual(sorted(stats[0]["pipes"]), ["cvt", "fma", "ls", "sfu", "t", "v"])
        self.check_bound_is_busiest_pipe(stats)

    def test_valhall_line_reads_exactly(self):
        # red_plastic high.dir1's fragment shader, the last line of mali-g57.txt.
        s = recorded("mali-g57")[-1]
        self.assertEqual((s["stage"], s["instructions"], s["threads"], s["spills"]), ("fragment", 270, 2, 0))
        self.assertEqual(s["cycles"], 2.421875)
        self.assertEqual(s["pipes"], {"fma": 2.421875, "cvt": 1.484375, "sfu": 0.875, "v": 0.625, "t": 0.5, "ls": 0.0})
        self.assertEqual(s["raw"]["quadwords"], 136)

    def test_bifrost_line_reads_exactly(self):
        s = recorded("mali-g52")[-1]
        self.assertEqual((s["stage"], s["instructions"], s["raw"]["tuples"], s["raw"]["clauses"]),
                         ("fragment", 239, 178, 24))
        self.assertAlmostEqual(s["cycles"], 7.333333)
        self.assertEqual(s["raw"]["preloads"], 10)

    def test_stage_names_map_to_package_stages(self):
        for gpu in ("mali-g52", "mali-g57"):
            stages = {s["stage"] for s in recorded(gpu)}
            self.assertIn("fragment", stages, gpu)
            self.assertTrue(stages & {"vertex", "vertex_position"}, gpu)

    def test_spills_fills_pair_is_split(self):
        parsed = shaderdb.parse_line("SHADER-DB: MESA_SHADER_FRAGMENT shader: 10 inst, 0.5 cycles, 0.5 fma, "
                                     "0.1 cvt, 0.2 sfu, 0.1 v, 0.25 t, 0.0 ls, 8 quadwords, 1 threads, "
                                     "0 loops, 3:4 spills:fills")
        s = shaderdb.normalise(parsed)
        self.assertEqual((s["spills"], s["fills"], s["threads"]), (3, 4, 1))


class AdrenoStatistics(unittest.TestCase):
    def test_categories_add_up_to_instructions(self):
        stats = recorded("adreno-630")
        self.assertTrue(stats)
        for s in stats:
            self.assertEqual(s["family"], "ir3")
            self.assertEqual(sum(s["categories"].values()), s["instructions"], s)
            self.assertIsNone(s["cycles"])
            self.assertGreater(s["registers"]["full"] + s["registers"]["half"], 0)

    def test_ir3_line_reads_exactly(self):
        s = recorded("adreno-630")[-1]
        self.assertEqual((s["stage"], s["instructions"], s["raw"]["nops"], s["waves"]), ("fragment", 230, 23, 16))
        self.assertEqual(s["registers"], {"full": 6, "half": 0})
        self.assertEqual((s["categories"]["cat4"], s["categories"]["cat5"], s["raw"]["(ss)"]), (10, 2, 6))

    def test_binning_pass_vertex_shader_is_its_own_stage(self):
        stages = [s["stage"] for s in recorded("adreno-630")]
        self.assertIn("fragment", stages)
        self.assertIn("vertex", stages)
        self.assertIn("vertex_binning", stages)


class Robustness(unittest.TestCase):
    def test_other_debug_messages_are_skipped(self):
        self.assertIsNone(shaderdb.parse_line("FS compile failed: missing precision"))
        self.assertIsNone(shaderdb.parse_line("GL_INVALID_ENUM in glEnable(0x1234)"))
        self.assertEqual(shaderdb.parse_messages(["", "hello", "FRAGMENT shader: 1 inst"]), [])

    def test_unreadable_item_is_an_error_not_a_guess(self):
        with self.assertRaises(shaderdb.ParseError):
            shaderdb.parse_line("FRAG shader: 12 inst, lots of nops")

    def test_unknown_field_set_is_an_error(self):
        with self.assertRaises(shaderdb.ParseError):
            shaderdb.normalise(shaderdb.parse_line("FRAG shader: 12 inst, 3 widgets"))


class MatcCostFigures(unittest.TestCase):
    """tools/mesa_stats/package_glsl.py reads `matc info --json`'s per-variant costs (recorded in
    matc-info-red_plastic.json) to pair each variant's statistics with the cost figures, under the
    names matc gives them."""

    def recorded(self):
        with open(os.path.join(FIXTURES, "matc-info-red_plastic.json")) as f:
            return json.load(f)

    def test_recorded_costs_read_every_variant_and_stage(self):
        costs = package_glsl.read_costs(self.recorded())
        self.assertEqual(len(costs), 8)
        self.assertEqual(sorted(costs["high.dir1"]), ["fragment", "vertex"])
        fragment = costs["high.dir1"]["fragment"]
        self.assertEqual({k: fragment[k] for k in ("alu", "scalar_alu", "transcendental", "divisions", "textures",
                                                   "varying_components")},
                         {"alu": 80, "scalar_alu": 154, "transcendental": 5, "divisions": 3, "textures": 2,
                          "varying_components": 6})
        self.assertAlmostEqual(fragment["relaxed_percent"], 94.1, places=1)
        self.assertAlmostEqual(fragment["cycles"], 1.37, places=2)

    def test_a_matc_without_costs_is_an_error_not_an_empty_table(self):
        info = self.recorded()
        for v in info["variants"]:
            del v["costs"]
        with self.assertRaises(RuntimeError):
            package_glsl.read_costs(info)

    def test_a_stage_matc_could_not_cost_is_an_error_not_a_silent_drop(self):
        info = self.recorded()
        info["variants"][0]["costs"]["fragment"] = {"error": "malformed SPIR-V"}
        with self.assertRaises(RuntimeError):
            package_glsl.read_costs(info)


if __name__ == "__main__":
    unittest.main(verbosity=2)
