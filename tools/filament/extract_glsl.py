#!/usr/bin/env python3
"""Extract the GLSL shaders stored in a Filament material package (.filamat).

Written for packages produced by Filament's `matc` 1.9.25 (Debian package
libfilament-tools, material format version 10), e.g.

    matc -p mobile -a opengl -o red.filamat red_plastic.mat

Usage:
    extract_glsl.py FILE.filamat --list
    extract_glsl.py FILE.filamat --variant N --stage fragment [--model mobile] [-o OUT]
    extract_glsl.py FILE.filamat --all DIR

Format notes (Filament 1.9, written from reading its filamat/filaflat sources):

* The file is a flat sequence of chunks: an 8-byte tag (a uint64 stored little
  endian, so "MAT_GLSL" appears reversed in a hex dump), a uint32 little-endian
  payload size, then the payload.  There is no file header.
* "DIC_TEXT" (the text line dictionary, shared by the GLSL and Metal chunks):
  uint32 string count, then that many NUL-terminated strings (one source line
  each, without its newline).
* "MAT_GLSL": uint64 shader count, then per shader an index record of
  uint8 shader model (1 = GL_ES_30 "mobile", 2 = GL_CORE_41 "desktop"),
  uint8 variant key, uint8 stage (0 = vertex, 1 = fragment) and a uint32
  offset, relative to the start of the chunk payload, of the shader body.
  Identical shaders share one body.  A body is: uint32 text size (length + 1
  for the terminating NUL), uint32 line count, then one uint16 dictionary index
  per line; the text is the lines joined with (and each followed by) "\\n".
* Variant key bits (filament Variant.h in 1.9): 0x01 DIR directional light,
  0x02 DYN dynamic (point/spot) lights, 0x04 SRE shadow receiver, 0x08 SKN
  skinning/morphing, 0x10 DEP depth-only, 0x20 FOG, 0x40 VSM variance shadow
  maps.  Vertex shaders are stored under key & 0x1f (plus VSM for depth
  variants), fragment shaders under key & 0x77, so e.g. the fragment variant
  0x21 (DIR|FOG) is drawn with the vertex shader 0x01.

Standard library only.  Exit status: 0 on success, 1 on a malformed or
unsupported file or a missing shader, 2 on a usage error.
"""

import argparse
import os
import struct
import sys

SUPPORTED_MATERIAL_VERSION = 10  # Filament 1.9.x (matc 1.9.25)

MODEL_NAMES = {1: "mobile", 2: "desktop"}   # ShaderModel::GL_ES_30, GL_CORE_41
MODEL_IDS = {v: k for k, v in MODEL_NAMES.items()}
MODEL_DETAIL = {1: "GL_ES_30", 2: "GL_CORE_41"}
STAGE_NAMES = {0: "vertex", 1: "fragment"}  # ShaderType::VERTEX, FRAGMENT
STAGE_IDS = {"vertex": 0, "vert": 0, "vs": 0, "fragment": 1, "frag": 1, "fs": 1}
STAGE_EXT = {0: "vert", 1: "frag"}

VARIANT_BITS = [
    (0x01, "DIR"),  # directional lighting
    (0x02, "DYN"),  # dynamic lighting (point, spot lights)
    (0x04, "SRE"),  # shadow receiver
    (0x08, "SKN"),  # skinning or morphing
    (0x10, "DEP"),  # depth only
    (0x20, "FOG"),  # fog
    (0x40, "VSM"),  # variance shadow maps
]
VERTEX_MASK = 0x1f    # DIR | DYN | SRE | SKN | DEP
FRAGMENT_MASK = 0x77  # DIR | DYN | SRE | FOG | DEP | VSM
DEPTH = 0x10
VSM = 0x40


class FormatError(Exception):
    """The input is not a readable Filament 1.9 material package."""


class UsageError(Exception):
    """The request cannot be satisfied (e.g. no such shader)."""


def tag_name(tag):
    raw = struct.pack(">Q", tag)
    if all(32 <= b < 127 for b in raw):
        return raw.decode("ascii")
    return "0x%016x" % tag


def variant_flags(key):
    names = [name for bit, name in VARIANT_BITS if key & bit]
    if key & 0x80:
        names.append("0x80?")
    return "|".join(names) if names else "-"


def stored_key(key, stage):
    """The key under which Filament 1.9 stores the shader of `stage` for variant `key`."""
    if stage == 0:
        return key & ((VERTEX_MASK | VSM) if key & DEPTH else VERTEX_MASK)
    return key & FRAGMENT_MASK


def read_chunks(data):
    chunks = {}
    order = []
    pos = 0
    while pos < len(data):
        if len(data) - pos < 12:
            raise FormatError("truncated chunk header at offset %d (%d bytes left)"
                              % (pos, len(data) - pos))
        tag, size = struct.unpack_from("<QI", data, pos)
        name = tag_name(tag)
        if pos == 0 and not (name.startswith("MAT_") or name.startswith("DIC_")):
            raise FormatError("does not start with a Filament chunk tag (MAT_*/DIC_*): "
                              "not a .filamat material package")
        start = pos + 12
        end = start + size
        if end > len(data):
            raise FormatError("chunk %s at offset %d claims %d bytes but only %d remain"
                              % (name, pos, size, len(data) - start))
        if name in chunks:
            raise FormatError("duplicate chunk %s at offset %d" % (name, pos))
        chunks[name] = (start, end)
        order.append(name)
        pos = end
    return chunks, order


def read_dictionary(data, start, end):
    if end - start < 4:
        raise FormatError("DIC_TEXT chunk too small")
    (count,) = struct.unpack_from("<I", data, start)
    lines = []
    pos = start + 4
    for i in range(count):
        nul = data.find(b"\0", pos, end)
        if nul < 0:
            raise FormatError("DIC_TEXT: string %d of %d is not NUL-terminated" % (i, count))
        lines.append(data[pos:nul])
        pos = nul + 1
    if pos != end:
        raise FormatError("DIC_TEXT: %d trailing bytes after %d strings" % (end - pos, count))
    return lines


class Shader(object):
    def __init__(self, index, model, variant, stage, offset):
        self.index = index
        self.model = model
        self.variant = variant
        self.stage = stage
        self.offset = offset
        self.text = None
        self.declared_size = None


def read_glsl_chunk(data, start, end, dictionary):
    size = end - start
    if size < 8:
        raise FormatError("MAT_GLSL chunk too small")
    (count,) = struct.unpack_from("<Q", data, start)
    if count == 0 or 8 + 7 * count > size:
        raise FormatError("MAT_GLSL: implausible shader count %d for a %d-byte chunk"
                          % (count, size))
    shaders = []
    for i in range(count):
        model, variant, stage, offset = struct.unpack_from("<BBBI", data, start + 8 + 7 * i)
        if model not in MODEL_NAMES:
            raise FormatError("MAT_GLSL entry %d: unknown shader model %d" % (i, model))
        if stage not in STAGE_NAMES:
            raise FormatError("MAT_GLSL entry %d: unknown stage %d" % (i, stage))
        if offset < 8 + 7 * count or offset + 8 > size:
            raise FormatError("MAT_GLSL entry %d: shader offset %d outside the chunk"
                              % (i, offset))
        shaders.append(Shader(i, model, variant, stage, offset))

    cache = {}
    for sh in shaders:
        if sh.offset not in cache:
            pos = start + sh.offset
            text_size, nlines = struct.unpack_from("<II", data, pos)
            pos += 8
            if pos + 2 * nlines > end:
                raise FormatError("MAT_GLSL: shader at offset %d has %d lines, beyond the chunk"
                                  % (sh.offset, nlines))
            indices = struct.unpack_from("<%dH" % nlines, data, pos)
            parts = []
            for li in indices:
                if li >= len(dictionary):
                    raise FormatError("MAT_GLSL: line index %d outside the dictionary (%d lines)"
                                      % (li, len(dictionary)))
                parts.append(dictionary[li])
                parts.append(b"\n")
            cache[sh.offset] = (b"".join(parts), text_size)
        sh.text, sh.declared_size = cache[sh.offset]
    return shaders


def load(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise FormatError("cannot read %s: %s" % (path, e.strerror or e))
    if not data:
        raise FormatError("%s is empty" % path)
    chunks, order = read_chunks(data)
    if "MAT_VERS" not in chunks:
        raise FormatError("no MAT_VERS chunk: not a Filament material package")
    vs, ve = chunks["MAT_VERS"]
    if ve - vs != 4:
        raise FormatError("MAT_VERS chunk has size %d, expected 4" % (ve - vs))
    (version,) = struct.unpack_from("<I", data, vs)
    if version != SUPPORTED_MATERIAL_VERSION:
        sys.stderr.write("warning: material format version %d, this tool was written for "
                         "version %d (Filament 1.9); continuing\n"
                         % (version, SUPPORTED_MATERIAL_VERSION))
    name = None
    if "MAT_NAME" in chunks:
        ns, ne = chunks["MAT_NAME"]
        name = data[ns:ne].split(b"\0", 1)[0].decode("utf-8", "replace")
    if "MAT_GLSL" not in chunks:
        others = [c for c in ("MAT_SPIR", "MAT_METL") if c in chunks]
        hint = (" (it holds %s only: compile with matc -a opengl or -a all)" % ", ".join(others)
                if others else "")
        raise FormatError("%s has no GLSL (MAT_GLSL) chunk%s" % (path, hint))
    if "DIC_TEXT" not in chunks:
        extra = (" (it has DIC_GLSL: a newer Filament layout, unsupported)"
                 if "DIC_GLSL" in chunks else "")
        raise FormatError("%s has no DIC_TEXT line dictionary chunk%s" % (path, extra))
    dictionary = read_dictionary(data, *chunks["DIC_TEXT"])
    shaders = read_glsl_chunk(data, *chunks["MAT_GLSL"], dictionary=dictionary)
    for sh in shaders:
        if sh.declared_size != len(sh.text) + 1:
            sys.stderr.write("warning: shader #%d: declared size %d, reconstructed %d bytes\n"
                             % (sh.index, sh.declared_size - 1, len(sh.text)))
    return version, name, shaders


def parse_variant(s):
    try:
        v = int(s, 0)
    except ValueError:
        raise argparse.ArgumentTypeError("not a number: %r (use e.g. 1, 0x21)" % s)
    if not 0 <= v <= 255:
        raise argparse.ArgumentTypeError("variant must be in 0..255")
    return v


def cmd_list(version, name, shaders, out):
    out.write("# material %s, format version %d, %d GLSL shaders (%d distinct)\n"
              % (name or "?", version, len(shaders), len({s.offset for s in shaders})))
    out.write("# %-3s %-7s %-11s %-22s %-8s %s\n"
              % ("#", "model", "variant", "flags", "stage", "bytes"))
    for sh in shaders:
        dup = [o.index for o in shaders if o.offset == sh.offset and o.index < sh.index]
        note = ("  (same text as #%d)" % dup[0]) if dup else ""
        out.write("  %-3d %-7s %-11s %-22s %-8s %d%s\n"
                  % (sh.index, MODEL_NAMES[sh.model], "%d (0x%02x)" % (sh.variant, sh.variant),
                     variant_flags(sh.variant), STAGE_NAMES[sh.stage], len(sh.text), note))


def select(shaders, variant, stage, model_name):
    models = sorted({s.model for s in shaders})
    if model_name is None:
        model = 1 if 1 in models else models[0]
    else:
        model = MODEL_IDS[model_name]
        if model not in models:
            raise UsageError("no %s (%s) shaders in this file; it has: %s"
                             % (model_name, MODEL_DETAIL[model],
                                ", ".join(MODEL_NAMES[m] for m in models)))
    for s in shaders:
        if s.model == model and s.variant == variant and s.stage == stage:
            return s
    have = sorted({s.variant for s in shaders if s.model == model and s.stage == stage})
    msg = ("no %s %s shader for variant 0x%02x (%d, %s)"
           % (MODEL_NAMES[model], STAGE_NAMES[stage], variant, variant, variant_flags(variant)))
    alt = stored_key(variant, stage)
    if alt != variant and alt in have:
        msg += ("; Filament 1.9 uses the %s shader of variant 0x%02x (%d, %s) for it"
                % (STAGE_NAMES[stage], alt, alt, variant_flags(alt)))
    msg += "\navailable %s variants: %s" % (
        STAGE_NAMES[stage], " ".join("0x%02x" % v for v in have) or "none")
    raise UsageError(msg)


def write_bytes(path, text):
    if path is None or path == "-":
        sys.stdout.buffer.write(text)
        sys.stdout.buffer.flush()
    else:
        try:
            with open(path, "wb") as f:
                f.write(text)
        except OSError as e:
            raise UsageError("cannot write %s: %s" % (path, e.strerror or e))


def main(argv=None):
    ap = argparse.ArgumentParser(
        description="List or extract the GLSL shaders of a Filament 1.9 .filamat package.")
    ap.add_argument("file", help="compiled material package (.filamat) from matc 1.9")
    ap.add_argument("--list", action="store_true", help="list the stored shaders")
    ap.add_argument("--variant", type=parse_variant,
                    help="variant key, decimal or 0x hex (e.g. 1 = directional light only)")
    ap.add_argument("--stage", choices=sorted(STAGE_IDS), help="shader stage")
    ap.add_argument("--model", choices=sorted(MODEL_IDS),
                    help="shader model (default: mobile if present)")
    ap.add_argument("-o", "--output", help="output file (default: standard output)")
    ap.add_argument("--all", metavar="DIR",
                    help="write every shader to DIR/<model>_v<NN>.<vert|frag>")
    args = ap.parse_args(argv)

    modes = sum([bool(args.list), args.all is not None, args.variant is not None])
    if modes != 1:
        ap.error("give exactly one of --list, --all DIR, or --variant N --stage STAGE")
    if args.variant is not None and args.stage is None:
        ap.error("--variant needs --stage vertex|fragment")
    if args.variant is None and (args.stage or args.output):
        ap.error("--stage and -o go with --variant N")

    try:
        version, name, shaders = load(args.file)
        if args.list:
            cmd_list(version, name, shaders, sys.stdout)
        elif args.all is not None:
            os.makedirs(args.all, exist_ok=True)
            for s in shaders:
                if args.model and s.model != MODEL_IDS[args.model]:
                    continue
                fn = os.path.join(args.all, "%s_v%02x.%s"
                                  % (MODEL_NAMES[s.model], s.variant, STAGE_EXT[s.stage]))
                write_bytes(fn, s.text)
                print(fn)
        else:
            s = select(shaders, args.variant, STAGE_IDS[args.stage], args.model)
            write_bytes(args.output, s.text)
    except FormatError as e:
        sys.stderr.write("%s: error: %s: %s\n" % (ap.prog, args.file, e))
        return 1
    except UsageError as e:
        sys.stderr.write("%s: error: %s\n" % (ap.prog, e))
        return 1
    except BrokenPipeError:
        # output piped into e.g. `head`: not an error; silence the flush at exit
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
