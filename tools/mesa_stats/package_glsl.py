"""A Facet package's own GLSL ES 3.00 shaders and static cost counts, read with `matc info`
(the package is the contract: what the runtime would hand the GL driver is what is measured)."""

import os
import subprocess

# `matc info` static cost table header -> the InstructionCounts field it prints
# (compiler/include/facet/compiler/mobile_cost.h); the data files keep them under "spirv_cost".
COST_COLUMNS = {
    "alu": "aluOps",
    "scalar": "scalarAluOps",
    "transc": "transcendentalOps",
    "div": "divisions",
    "tex": "textureSamples",
    "varyings": "varyingComponents",
    "mediump": "relaxedPercent",
    "cycles": "mobileCostCycles",  # the mobile cost model's estimate, where matc prints it
}


def parse_cost_table(text):
    """{variant: {stage: {InstructionCounts field: number}}} from `matc info`'s static cost table (its
    title may span lines; the header row starts with "variant stage")."""
    lines = text.splitlines()
    try:
        start = next(i for i, l in enumerate(lines) if l.startswith("static cost"))
        head = next(i for i in range(start + 1, len(lines)) if lines[i].split()[:2] == ["variant", "stage"])
    except StopIteration:
        raise RuntimeError("matc info printed no static cost table")
    header = lines[head].split()
    unknown = [h for h in header[2:] if h not in COST_COLUMNS]
    if unknown:
        raise RuntimeError("unknown cost table column(s) %s in %r" % (", ".join(unknown), lines[head]))
    costs = {}
    for line in lines[head + 1:]:
        if not line.startswith("  "):
            break
        cells = line.split()
        if len(cells) != len(header):
            raise RuntimeError("unreadable cost table row: %r" % line)
        row = {}
        for name, cell in zip(header[2:], cells[2:]):
            row[COST_COLUMNS[name]] = float(cell.rstrip("%")) if cell.endswith("%") or "." in cell else int(cell)
        costs.setdefault(cells[0], {})[cells[1]] = row
    return costs


def package_pairs(matc, pkg, work, variants=None):
    """Writes each variant's GLSL ES vertex and fragment shader from the package into `work`;
    returns ([{"name": variant, "vertex": path, "fragment": path}], cost table). `variants`
    limits the variants (default: all the package has)."""
    info = subprocess.run([matc, "info", pkg], check=True, capture_output=True, text=True).stdout
    costs = parse_cost_table(info)
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
