#!/usr/bin/env python3
"""Collects Mesa's shader-db statistics for every variant of every example material, per GPU,
beside the static SPIR-V cost counts `matc info` gives for the same variant and the cost model's
operation counts (tools/mesa_stats/spirv_op_counts: the calibration's features), into one JSON file
(the calibration data of docs/mesa-statistics.md).

  cmake --build build/test --target matc spirv_op_counts
  tools/mesa_stats/collect.py -o tools/calibration/mesa-stats.json

Needs scripts/build-mesa-shader-compilers.sh to have run (exit 2 otherwise).
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesa_compile  # noqa: E402
import package_glsl  # noqa: E402

SOURCE_ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# The fit's example rows: the four standard-model materials it was designed on (4 tiers x 2 light
# counts each; tests/gpu_stats/test_mesa_calibration.py counts them). A material added to
# examples/ (a coat, cloth, anisotropy) would change the fit's training set, not only refresh it.
CALIBRATION_MATERIALS = ("banded_ceramic", "brushed_gold", "painted_tiles", "red_plastic")


def build_material(matc, counter, mat, work):
    """Compiles the material into a package; returns its GLSL ES pairs (read back from the
    package), matc info's cost counts and the op-class counts, all keyed "<material>/<variant>"."""
    name = os.path.splitext(os.path.basename(mat))[0]
    pkg = os.path.join(work, name + ".matpkg")
    # The presets, not a tuning file's tiers: the tuning files are chosen on the calibrated
    # estimate this data fits, so reading them would make each collection depend on the last fit.
    subprocess.run([matc, "compile", mat, "--no-tuning", "-o", pkg], check=True, stdout=subprocess.DEVNULL)
    pairs, costs = package_glsl.package_pairs(matc, pkg, os.path.join(work, name))
    ops = json.loads(subprocess.run([counter, pkg], check=True, capture_output=True, text=True).stdout)[pkg]
    for p in pairs:
        p["name"] = "%s/%s" % (name, p["name"])
    return (pairs, {"%s/%s" % (name, k): v for k, v in costs.items()},
            {"%s/%s" % (name, k): v for k, v in ops.items()})


def dumps(obj, depth=0, flat_below=4):
    """JSON with one line per variant and GPU (objects at depth >= flat_below), so the file stays
    small and a change in one compiler's output is one changed line in a diff."""
    if not isinstance(obj, dict) or depth >= flat_below or not obj:
        return json.dumps(obj, sort_keys=True)
    pad = " " * (depth + 1)
    items = ["%s%s: %s" % (pad, json.dumps(k), dumps(obj[k], depth + 1, flat_below)) for k in sorted(obj)]
    return "{\n" + ",\n".join(items) + "\n" + " " * depth + "}"


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--matc", default=os.path.join(SOURCE_ROOT, "build", "test", "matc", "matc"))
    ap.add_argument("--counts", default=os.path.join(SOURCE_ROOT, "build", "test", "tests", "spirv_op_counts"))
    mesa_compile.add_gpu_arguments(ap)
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args(argv)

    gpus = mesa_compile.gpus_to_collect(args, "collect")
    if gpus is None:
        return mesa_compile.EXIT_NOT_BUILT

    materials = [os.path.join(SOURCE_ROOT, "examples", "materials", m + ".mat") for m in CALIBRATION_MATERIALS]
    with tempfile.TemporaryDirectory(prefix="facet-mesa-stats-") as work:
        pairs, costs, op_counts = [], {}, {}
        for mat in materials:
            p, c, o = build_material(args.matc, args.counts, mat, work)
            pairs += p
            costs.update(c)
            op_counts.update(o)
        try:
            measured = mesa_compile.collect(args.prefix, gpus, pairs)
        except RuntimeError as e:
            sys.stderr.write("collect: %s\n" % e)
            return 1

    variants = {}
    for pair in pairs:
        name = pair["name"]
        entry = {"spirv_cost": costs[name], "op_counts": op_counts[name], "gpus": {}}
        for gpu in gpus:
            shaders = measured[gpu]["shaders"][name]
            # Every stage the driver printed: Mali's vertex shader arrives as its IDVS halves
            # (vertex_position, vertex_varying), Adreno's with a binning-pass copy.
            entry["gpus"][gpu] = shaders
        variants[name] = entry
    data = {
        "generated_by": "tools/mesa_stats/collect.py -o tools/calibration/mesa-stats.json",
        "mesa": "Debian 22.3.6 (scripts/build-mesa-shader-compilers.sh)",
        "materials": [os.path.relpath(m, SOURCE_ROOT) for m in materials],
        "gpus": {g: {"renderer": measured[g]["renderer"], "version": measured[g]["version"]} for g in gpus},
        "variants": variants,
    }
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w") as f:
        f.write(dumps(data) + "\n")
    sys.stderr.write("collect: %d variants x %d GPUs -> %s\n" % (len(variants), len(gpus), args.output))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
