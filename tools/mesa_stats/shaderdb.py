"""Parses the shader-db statistics lines Mesa's mobile compilers print (Mesa 22.3 formats).

One line per compiled shader, as GL debug messages (KHR_debug, type OTHER) or, for panfrost with
BIFROST_MESA_DEBUG=shaderdb, on stderr prefixed "SHADER-DB: ". Each line is
"<STAGE> shader: <value> <name>, <value> <name>, ...". The formats, from the 22.3 sources:

  Bifrost (bi_print_stats, src/panfrost/bifrost/bifrost_compile.c):
    MESA_SHADER_FRAGMENT shader: 98 inst, 60 tuples, 17 clauses, 2.500000 cycles, 2.500000 arith,
    1.000000 texture, 0.375000 vary, 0.000000 ldst, 78 quadwords, 2 threads, 3 preloads,
    0 loops, 0:0 spills:fills                      ("preloads" only on v7)
    cycles = max(arith, texture, vary, ldst); arith = tuples / 24, texture = messages / 2,
    vary = 16-bit channels / 16, ldst = messages / 1 (the driver's normalised model of Arm's
    Mali Offline Compiler).
  Valhall (va_print_stats, same file):
    MESA_SHADER_FRAGMENT shader: 120 inst, 1.250000 cycles, 1.250000 fma, 0.312500 cvt,
    0.500000 sfu, 0.375000 v, 0.500000 t, 0.000000 ls, 61 quadwords, 2 threads, 0 loops,
    0:0 spills:fills
    cycles = max(fma, cvt, sfu, v, t, ls); fma = ops / 64, cvt = ops / 64, sfu = ops / 16,
    v = varying channels / 16, t = texture ops / 4, ls = messages / 1 (Mali-G78 peak rates).
  Mali stage names also include MESA_SHADER_POSITION and MESA_SHADER_VARYING: the two halves of
  an index-driven vertex shader (IDVS), and MESA_SHADER_BLEND for internal blend shaders.
  Threads: 2 when the shader uses at most 32 work registers (full occupancy), else 1.

  Adreno ir3 (dump_shader_info, src/gallium/drivers/freedreno/ir3/ir3_gallium.c):
    FRAG shader: 150 inst, 20 nops, 130 non-nops, 30 mov, 5 cov, 76 dwords, 40 last-baryf,
    4 half, 9 full, 32 constlen, 20 cat0, 35 cat1, 50 cat2, 20 cat3, 8 cat4, 2 cat5, 0 cat6,
    0 cat7, 0 stp, 0 ldp, 10 sstall, 3 (ss), 0 systall, 2 (sy), 4 waves, 0 loops
    Stages VERT, BVERT (the binning-pass vertex shader), FRAG. cat2 = 2-source ALU, cat3 =
    3-source ALU (mad), cat4 = special function unit (rcp, rsq, log2, exp2, sin, cos, sqrt),
    cat5 = texture, cat6 = memory. half/full = registers used (vec4 units), waves per SP.

This module has no dependency beyond the standard library, so its tests always run.
"""

import re

# "<value> <name>" items; the name may contain spaces-free punctuation: "(ss)", "last-baryf",
# "spills:fills" (its value is "a:b").
_ITEM = re.compile(r"^\s*(?P<value>-?\d+(?:\.\d+)?(?::\d+)?)\s+(?P<name>\S+)\s*$")
_LINE = re.compile(r"(?P<stage>[A-Z_]+) shader: (?P<items>.*)$")

# Mesa's stage names -> the stage names of Facet's packages.
_STAGES = {
    "MESA_SHADER_VERTEX": "vertex",
    "MESA_SHADER_POSITION": "vertex_position",
    "MESA_SHADER_VARYING": "vertex_varying",
    "MESA_SHADER_FRAGMENT": "fragment",
    "MESA_SHADER_BLEND": "blend",
    "MESA_SHADER_COMPUTE": "compute",
    "VERT": "vertex",
    "BVERT": "vertex_binning",
    "FRAG": "fragment",
    "CL": "compute",
}


class ParseError(ValueError):
    pass


def parse_line(line):
    """Returns {"stage_raw", "stage", "fields": {name: number}} for one statistics line, or None
    when the line is not a shader-db line (other debug output). Raises ParseError when a line
    starts like one but an item does not read as "<number> <name>"."""
    text = line.strip()
    if text.startswith("SHADER-DB:"):
        text = text[len("SHADER-DB:"):].strip()
    m = _LINE.match(text)
    if not m or m.group("stage") not in _STAGES:
        return None
    fields = {}
    for raw in m.group("items").split(","):
        if not raw.strip():
            continue
        item = _ITEM.match(raw)
        if not item:
            raise ParseError("unreadable statistics item %r in line %r" % (raw.strip(), text))
        value, name = item.group("value"), item.group("name")
        if name == "spills:fills":
            spills, fills = value.split(":") if ":" in value else (value, "0")
            fields["spills"], fields["fills"] = int(spills), int(fills)
            continue
        if ":" in value:
            raise ParseError("unexpected a:b value for %r in line %r" % (name, text))
        fields[name] = float(value) if "." in value else int(value)
    return {"stage_raw": m.group("stage"), "stage": _STAGES[m.group("stage")], "fields": fields}


def family_of(fields):
    """Which compiler printed these fields: "valhall", "bifrost" or "ir3"."""
    if "fma" in fields and "sfu" in fields:
        return "valhall"
    if "tuples" in fields and "arith" in fields:
        return "bifrost"
    if "nops" in fields and "cat2" in fields:
        return "ir3"
    raise ParseError("unknown statistics format with fields %s" % sorted(fields))


# The common view over the three formats; per-pipe figures keep the driver's own names.
_PIPES = {
    "bifrost": ["arith", "texture", "vary", "ldst"],
    "valhall": ["fma", "cvt", "sfu", "v", "t", "ls"],
}


def normalise(parsed):
    """One shader's statistics in a driver-independent shape:
    {"stage", "family", "instructions", "cycles" (Mali bound, else None),
     "pipes" {pipe: cycles} (Mali), "categories" {catN: count} (ir3), "registers"
     {"full", "half"} (ir3) , "threads" (Mali) / "waves" (ir3), "spills", "fills", "loops",
     "raw": every field as printed}."""
    f = parsed["fields"]
    family = family_of(f)
    out = {
        "stage": parsed["stage"],
        "family": family,
        "instructions": f["inst"],
        "loops": f.get("loops", 0),
        "raw": dict(f),
    }
    if family in _PIPES:
        out["cycles"] = f["cycles"]
        out["pipes"] = {p: f[p] for p in _PIPES[family]}
        out["threads"] = f["threads"]
        out["spills"] = f.get("spills", 0)
        out["fills"] = f.get("fills", 0)
    else:
        out["cycles"] = None
        out["categories"] = {"cat%d" % i: f["cat%d" % i] for i in range(8)}
        out["registers"] = {"full": f["full"], "half": f["half"]}
        out["waves"] = f["waves"]
        # ir3's line in 22.3 has no spill count: unknown, not zero.
        out["spills"] = None
        out["fills"] = None
    return out


def parse_messages(lines):
    """Every shader-db line among `lines`, normalised, in order; other lines are skipped."""
    result = []
    for line in lines:
        for part in line.splitlines():
            parsed = parse_line(part)
            if parsed is not None:
                result.append(normalise(parsed))
    return result
