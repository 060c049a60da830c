"""A Facet package's own GLSL ES 3.00 shaders and static cost figures, read with `matc info`
(the package is the contract: what the runtime would hand the GL driver is what is measured)."""

import json
import os
import subprocess


def read_costs(info):
    """{variant: {stage: {figure: number}}} from `matc info --json`'s document: each variant's
    "costs", under the cost model's figure names (compiler/cost_figures.h; docs/build-integration.md).
    The data files keep them under "spirv_cost"."""
    costs = {}
    for variant in info.get("variants", []):
        key = variant.get("key")
        if "costs" not in variant:
            raise RuntimeError("matc info --json gives variant %s no costs (a matc from before it did)" % key)
        for stage, figures in variant["costs"].items():
            if "error" in figures:
                raise RuntimeError("matc has no cost figures for %s %s: %s" % (key, stage, figures["error"]))
        costs[key] = variant["costs"]
    if not costs:
        raise RuntimeError("matc info --json lists no variants")
    return costs


def package_pairs(matc, pkg, work, variants=None):
    """Writes each variant's GLSL ES vertex and fragment shader from the package into `work`;
    returns ([{"name": variant, "vertex": path, "fragment": path}], cost figures). `variants`
    limits the variants (default: all the package has)."""
    info = subprocess.run([matc, "info", pkg, "--json"], check=True, capture_output=True, text=True).stdout
    costs = read_costs(json.loads(info))
    keys = list(costs) if variants is None else variants
    missing = [k for k in keys if k not in costs]
    if missing:
        raise RuntimeError("no variant %s (it has: %s)" % (", ".join(missing), ", ".join(costs)))
    os.makedirs(work, exist_ok=True)
    pairs = []
    for key in keys:
        pair = {"name": key}
        for stage in ("vertex", "fragment"):
            text = subprocess.run([matc, "info", pkg, "--variant", key, "--stage", stage, "--target", "glsl_es_300"],
                                  check=True, capture_output=True, text=True).stdout
            path = os.path.join(work, "%s.%s.glsl" % (key, stage))
            with open(path, "w") as f:
                f.write(text)
            pair[stage] = path
        pairs.append(pair)
    return pairs, {k: costs[k] for k in keys}
