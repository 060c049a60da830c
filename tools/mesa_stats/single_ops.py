#!/usr/bin/env python3
"""Measures what one GLSL operation costs on each fake GPU: fragment shaders that apply the
operation N times in a dependent chain to a vec4 varying, minus the same shader with no
operation, divided by N·4 (per scalar component). In mediump and highp.

  tools/mesa_stats/single_ops.py -o tools/calibration/mesa-single-ops.json

Beside the statistics, the same difference of the cost model's operation counts
(tools/mesa_stats/spirv_op_counts, countOpClasses of compiler/mobile_cost.h) over each fragment
shader's optimised SPIR-V (glslangValidator, then spirv-opt -O, the performance passes matc runs):
the features of the calibration (fit.py), so each op pins the weight of its class.

The chain's operands are varyings and uniforms, never constants, so the compilers cannot fold
it; each step depends on the previous one, so nothing is shared between steps. Needs
scripts/build-mesa-shader-compilers.sh (exit 2 otherwise).
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import collect  # noqa: E402
import mesa_compile  # noqa: E402

STEPS = 8

# name -> one step of the chain on `v` (vec4), with uniforms u[i] (vec4) and sampler s.
OPS = {
    "add": "v = v + u[{i}];",
    "mul": "v = v * u[{i}];",
    "mad": "v = v * u[{i}] + u[{j}];",
    "min": "v = min(v, u[{i}]);",
    "clamp01": "v = clamp(v * u[{i}], 0.0, 1.0);",
    "div": "v = u[{i}] / v;",
    "inversesqrt": "v = inversesqrt(v);",
    "sqrt": "v = sqrt(v);",
    "exp2": "v = exp2(v);",
    "log2": "v = log2(v);",
    "log": "v = log(v);",
    "exp": "v = exp(v);",
    # pow(pow(a, b), c) folds to pow(a, b·c) in NIR (ir3 showed it): a multiply between the
    # steps stops that, and the "mul" shader's figures are subtracted (MINUS).
    "pow": "v = pow(v, u[{i}]) * u[{j}];",
    "sin": "v = sin(v);",
    "cos": "v = cos(v);",
    "tan": "v = tan(v);",
    "acos": "v = acos(v);",
    "asin": "v = asin(v);",
    "atan": "v = atan(v);",
    "atan2": "v = atan(v, u[{i}]);",
    "floor": "v = floor(v * u[{i}]);",
    "fract": "v = fract(v * u[{i}]);",
    "dot3": "v = vec4(dot(v.xyz, u[{i}].xyz));",
    "normalize3": "v = vec4(normalize(v.xyz), v.w);",
    "length3": "v = vec4(length(v.xyz));",
    "mix": "v = mix(v, u[{i}], u[{j}]);",
    "texture": "v = texture(s, v.xy);",
}

# Ops whose chain needs a helper operation; that operation's own figures are subtracted.
MINUS = {"pow": "mul"}

VERTEX = """#version 300 es
layout(location = 0) in highp vec4 a_position;
out {p} vec4 v_in;
void main() {{
    v_in = a_position.wzyx;
    gl_Position = a_position;
}}
"""

FRAGMENT = """#version 300 es
precision {p} float;
in {p} vec4 v_in;
uniform {p} vec4 u[{n}];
uniform {p} sampler2D s;
layout(location = 0) out {p} vec4 fragColor;
void main() {{
    {p} vec4 v = v_in;
{body}
    fragColor = v;
}}
"""


def shaders(op, precision, steps):
    body = "\n".join("    " + OPS[op].format(i=k % 8, j=(k + 1) % 8) for k in range(steps)) if op else ""
    return VERTEX.format(p=precision), FRAGMENT.format(p=precision, n=8, body=body)


def spirv_counts(counter, frag_paths):
    """{path: countOpClasses of the fragment shader's optimised SPIR-V}. glslang compiles ES
    shaders to SPIR-V from version 310 only; `-G` (OpenGL SPIR-V) keeps the plain uniforms."""
    modules = []
    for path in frag_paths:
        source = path + ".310.frag"
        with open(path) as f, open(source, "w") as out:
            out.write(f.read().replace("#version 300 es", "#version 310 es", 1))
        raw, opt = path + ".spv", path + ".opt.spv"
        subprocess.run(["glslangValidator", "-G", "--auto-map-locations", "--auto-map-bindings", "-S", "frag",
                        source, "-o", raw], check=True, stdout=subprocess.DEVNULL)
        subprocess.run(["spirv-opt", "-O", raw, "-o", opt], check=True)
        modules.append(opt)
    counted = json.loads(subprocess.run([counter] + modules, check=True, capture_output=True, text=True).stdout)
    return {path: counted[m] for path, m in zip(frag_paths, modules)}


def measures(stats):
    """The figures compared per op: Mali pipes (cycles) and instructions, ir3 categories."""
    out = {"instructions": stats["instructions"]}
    if stats.get("pipes"):
        out.update(stats["pipes"])
    if stats.get("categories"):
        out["non-nops"] = stats["raw"]["non-nops"]
        out.update({k: v for k, v in stats["categories"].items() if k in ("cat2", "cat3", "cat4", "cat5")})
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    mesa_compile.add_gpu_arguments(ap)
    ap.add_argument("--counts", default=os.path.join(collect.SOURCE_ROOT, "build", "test", "tests", "spirv_op_counts"),
                    help="the spirv_op_counts program (cmake --build build/test --target spirv_op_counts)")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args(argv)
    gpus = mesa_compile.gpus_to_collect(args, "single_ops")
    if gpus is None:
        return mesa_compile.EXIT_NOT_BUILT

    pairs = []
    with tempfile.TemporaryDirectory(prefix="facet-single-ops-") as work:
        for precision in ("mediump", "highp"):
            for op in [None] + sorted(OPS):
                vs, fs = shaders(op, precision, STEPS)
                name = "%s/%s" % (precision, op or "baseline")
                base = os.path.join(work, name.replace("/", "_"))
                with open(base + ".vert", "w") as f:
                    f.write(vs)
                with open(base + ".frag", "w") as f:
                    f.write(fs)
                pairs.append({"name": name, "vertex": base + ".vert", "fragment": base + ".frag"})
        try:
            measured = mesa_compile.collect(args.prefix, gpus, pairs)
            counted = spirv_counts(args.counts, [p["fragment"] for p in pairs])
        except (RuntimeError, OSError, subprocess.CalledProcessError) as e:
            sys.stderr.write("single_ops: %s\n" % e)
            return 1
        counts_of = {p["name"]: counted[p["fragment"]] for p in pairs}

    def per_component(precision, table):
        base = table("%s/baseline" % precision)
        per_op = {}
        for op in sorted(OPS):
            m = table("%s/%s" % (precision, op))
            per_op[op] = {k: (m[k] - base[k]) / (STEPS * 4.0) for k in m}
        for op, helper in MINUS.items():
            per_op[op] = {k: v - per_op[helper][k] for k, v in per_op[op].items()}
        return {op: {k: round(v, 6) for k, v in per.items()} for op, per in per_op.items()}

    result = {}
    for gpu in gpus:
        shaders_of = measured[gpu]["shaders"]
        for precision in ("mediump", "highp"):
            result.setdefault(gpu, {})[precision] = per_component(
                precision, lambda name: measures(shaders_of[name]["fragment"]))
    op_counts = {p: per_component(p, lambda name: counts_of[name]) for p in ("mediump", "highp")}
    data = {
        "generated_by": "tools/mesa_stats/single_ops.py -o tools/calibration/mesa-single-ops.json",
        "meaning": "fragment statistics per scalar component of one operation: (shader with %d dependent "
                   "vec4 steps - shader with none) / (%d * 4); Mali pipes in cycles, counts in instructions"
                   % (STEPS, STEPS),
        "steps": {op: OPS[op] for op in OPS},
        "subtracted": MINUS,
        "gpus": result,
        "op_counts": op_counts,
    }
    with open(args.output, "w") as f:
        f.write(collect.dumps(data, flat_below=3) + "\n")
    sys.stderr.write("single_ops: %d ops x 2 precisions x %d GPUs -> %s\n" % (len(OPS), len(gpus), args.output))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
