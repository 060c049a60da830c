#!/usr/bin/env python3
"""Compiles GLSL ES vertex+fragment pairs with Mesa's mobile compilers on drm-shim fake devices and
returns their shader-db statistics as JSON (docs/mesa-statistics.md).

  mesa_compile.py --gpu mali-g52[,adreno-630,...] PAIRS.json  > stats.json
  mesa_compile.py --gpu mali-g57 --vertex a.vert --fragment a.frag
  mesa_compile.py --gpu mali-g57 --matc build/test/matc/matc --package red.matpkg [--variant high.dir1]

PAIRS.json is a list of {"name", "vertex", "fragment"} (paths to GLSL ES source). Output:
{"gpus": {gpu: {"renderer", "version", "shaders": {name: {stage: stats, "other": [...]}}}}},
stats as tools/mesa_stats/shaderdb.py normalises them. The Mesa build is looked for in
$MESA_PREFIX, else $MESA_CACHE_DIR/install, else the build script's default cache folder. Exit 2 when the compilers are not built
(scripts/build-mesa-shader-compilers.sh), 1 when a shader does not compile (with the driver's log).

Python with ctypes rather than a C++ tool: the Mesa libraries live in a cache prefix outside the
project and must be loaded in a fresh process per GPU (LD_PRELOAD of the fake device, driver
environment), which a script that re-executes itself does in a few lines; no CMake target is
needed on machines without the compilers, and the calibration fit reads the same JSON.
"""

import argparse
import ctypes
import glob
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import package_glsl  # noqa: E402
import shaderdb  # noqa: E402

# The fake devices. Mali GPU ids as panfrost's drm-shim reads them (PAN_GPU_ID, hex);
# Adreno chip ids as freedreno's (FD_GPU_ID, decimal).
GPUS = {
    "mali-g52": {"shim": "panfrost", "env": {"PAN_GPU_ID": "7212"}},   # Bifrost v7
    "mali-g57": {"shim": "panfrost", "env": {"PAN_GPU_ID": "9093"}},   # Valhall v9
    "adreno-630": {"shim": "freedreno", "env": {"FD_GPU_ID": "630",
                                                "MESA_LOADER_DRIVER_OVERRIDE": "msm"}},
}

# The compilers' own variables for printing what they emit (--disassembly): panfrost's Bifrost and
# Valhall backend prints its NIR and final code under BIFROST_MESA_DEBUG=shaders, ir3 the vertex
# and fragment shaders' under IR3_SHADER_DEBUG=vs,fs.
DISASSEMBLY_ENV = {"panfrost": {"BIFROST_MESA_DEBUG": "shaders"}, "freedreno": {"IR3_SHADER_DEBUG": "vs,fs"}}

EXIT_NOT_BUILT = 2


def default_prefix():
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.environ.get("MESA_PREFIX") or os.path.join(
        os.environ.get("MESA_CACHE_DIR") or os.path.join(cache, "facet", "mesa"), "install")


def find_shim(prefix, shim):
    found = sorted(glob.glob(os.path.join(prefix, "lib", "*%s_noop_drm_shim.so" % shim)))
    return found[0] if found else None


def missing_reason(prefix, gpus):
    """Why the compilers for `gpus` cannot run here, or None."""
    if not os.path.exists(os.path.join(prefix, "lib", "libEGL.so.1")):
        return "no Mesa build at %s (run scripts/build-mesa-shader-compilers.sh)" % prefix
    for gpu in gpus:
        if gpu not in GPUS:
            return "unknown GPU '%s' (known: %s)" % (gpu, ", ".join(sorted(GPUS)))
        if not find_shim(prefix, GPUS[gpu]["shim"]):
            return "no %s drm-shim in %s/lib" % (GPUS[gpu]["shim"], prefix)
    return None


def add_gpu_arguments(parser):
    """--gpu and --prefix, as every collecting tool takes them."""
    parser.add_argument("--gpu", default="mali-g52,mali-g57,adreno-630", help="comma-separated: " + ", ".join(sorted(GPUS)))
    parser.add_argument("--prefix", default=default_prefix(), help="Mesa install prefix (default: %(default)s)")


def gpus_to_collect(args, tool):
    """The GPUs of --gpu, or None after saying on stderr why their compilers cannot run."""
    gpus = [g for g in args.gpu.split(",") if g]
    reason = missing_reason(args.prefix, gpus)
    if reason:
        sys.stderr.write("%s: %s\n" % (tool, reason))
        return None
    return gpus


def child_environment(prefix, gpu, disassembly=False):
    env = dict(os.environ)
    lib = os.path.join(prefix, "lib")
    env["LD_PRELOAD"] = find_shim(prefix, GPUS[gpu]["shim"])
    env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    env["LIBGL_DRIVERS_PATH"] = os.path.join(lib, "dri")
    env["EGL_PLATFORM"] = "surfaceless"
    # Without this a repeated compile comes from the disk cache and prints no statistics.
    env["MESA_SHADER_CACHE_DISABLE"] = "true"
    # ir3 prints statistics only with this flag; Mali's go to the GL debug callback regardless.
    env["FD_MESA_DEBUG"] = "shaderdb"
    # Gallium's threaded context drops synchronous debug callbacks (u_threaded_context.c,
    # tc_set_debug_callback): freedreno's statistics would vanish. shader-db runs without it too.
    env["GALLIUM_THREAD"] = "0"
    env.pop("MESA_LOADER_DRIVER_OVERRIDE", None)
    env.update(GPUS[gpu]["env"])
    if disassembly:
        env.update(DISASSEMBLY_ENV[GPUS[gpu]["shim"]])
    return env


# --- the child: one GLES context on one fake device ------------------------------------------

EGL_PLATFORM_SURFACELESS_MESA = 0x31DD
EGL_OPENGL_ES_API = 0x30A0
EGL_CONTEXT_MAJOR_VERSION = 0x3098
EGL_CONTEXT_MINOR_VERSION = 0x30FB
EGL_NONE = 0x3038
EGL_VENDOR, EGL_VERSION = 0x3053, 0x3054
GL_VERTEX_SHADER, GL_FRAGMENT_SHADER = 0x8B31, 0x8B30
GL_COMPILE_STATUS, GL_LINK_STATUS, GL_INFO_LOG_LENGTH = 0x8B81, 0x8B82, 0x8B84
GL_DEBUG_OUTPUT, GL_DEBUG_OUTPUT_SYNCHRONOUS = 0x92E0, 0x8242
GL_DONT_CARE = 0x1100
GL_RENDERER, GL_VERSION = 0x1F01, 0x1F02

DEBUGPROC = ctypes.CFUNCTYPE(None, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint,
                             ctypes.c_int, ctypes.c_char_p, ctypes.c_void_p)


class GlesContext:
    def __init__(self, prefix):
        lib = os.path.join(prefix, "lib")
        self.egl = ctypes.CDLL(os.path.join(lib, "libEGL.so.1"))
        self.gl = ctypes.CDLL(os.path.join(lib, "libGLESv2.so.2"))
        egl = self.egl
        egl.eglGetProcAddress.restype = ctypes.c_void_p
        egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
        get_display = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_uint, ctypes.c_void_p, ctypes.c_void_p)(
            egl.eglGetProcAddress(b"eglGetPlatformDisplayEXT"))
        self.dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, None, None)
        if not self.dpy:
            raise RuntimeError("eglGetPlatformDisplayEXT(surfaceless) failed")
        egl.eglInitialize.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
        if not egl.eglInitialize(self.dpy, None, None):
            raise RuntimeError("eglInitialize failed on the surfaceless display (is the drm-shim preloaded?)")
        egl.eglBindAPI(EGL_OPENGL_ES_API)
        # No EGL_CONTEXT_OPENGL_DEBUG: Mesa 22.3 rejects it for ES (EGL_BAD_ATTRIBUTE); enabling
        # GL_DEBUG_OUTPUT below delivers the messages all the same.
        attribs = (ctypes.c_int * 5)(EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE)
        egl.eglCreateContext.restype = ctypes.c_void_p
        egl.eglCreateContext.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
        self.ctx = egl.eglCreateContext(self.dpy, None, None, attribs)  # EGL_KHR_no_config_context
        if not self.ctx:
            raise RuntimeError("eglCreateContext(GLES 3.0, no config) failed: 0x%x" % egl.eglGetError())
        egl.eglMakeCurrent.argtypes = [ctypes.c_void_p] * 4
        if not egl.eglMakeCurrent(self.dpy, None, None, self.ctx):
            raise RuntimeError("eglMakeCurrent(surfaceless) failed: 0x%x" % egl.eglGetError())

        gl = self.gl
        gl.glGetString.restype = ctypes.c_char_p
        self.renderer = gl.glGetString(GL_RENDERER).decode()
        self.version = gl.glGetString(GL_VERSION).decode()
        self.messages = []
        self._callback = DEBUGPROC(self._on_message)  # kept alive as long as the context
        gl.glEnable(GL_DEBUG_OUTPUT)
        gl.glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS)
        set_callback = ctypes.CFUNCTYPE(None, DEBUGPROC, ctypes.c_void_p)(
            egl.eglGetProcAddress(b"glDebugMessageCallbackKHR"))
        set_callback(self._callback, None)
        control = ctypes.CFUNCTYPE(None, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_int,
                                   ctypes.c_void_p, ctypes.c_ubyte)(
            egl.eglGetProcAddress(b"glDebugMessageControlKHR"))
        control(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, None, 1)
        gl.glCreateShader.restype = ctypes.c_uint
        gl.glCreateProgram.restype = ctypes.c_uint

    def _on_message(self, source, type_, id_, severity, length, message, user):
        self.messages.append(ctypes.string_at(message, length).decode(errors="replace"))

    def _log(self, getter, obj):
        n = ctypes.c_int(0)
        getattr(self.gl, getter + "iv")(obj, GL_INFO_LOG_LENGTH, ctypes.byref(n))
        buf = ctypes.create_string_buffer(max(n.value, 1))
        getattr(self.gl, getter + "InfoLog")(obj, len(buf), None, buf)
        return buf.value.decode(errors="replace")

    def _shader(self, kind, source):
        gl = self.gl
        s = gl.glCreateShader(kind)
        text = ctypes.c_char_p(source.encode())
        gl.glShaderSource(s, 1, ctypes.byref(text), None)
        gl.glCompileShader(s)
        ok = ctypes.c_int(0)
        gl.glGetShaderiv(s, GL_COMPILE_STATUS, ctypes.byref(ok))
        if not ok.value:
            raise CompileError(self._log("glGetShader", s))
        return s

    def compile_pair(self, vertex_source, fragment_source):
        """Links the pair (Mesa compiles the driver variants at link); returns the statistics
        lines the driver reported meanwhile."""
        gl = self.gl
        self.messages = []
        vs = self._shader(GL_VERTEX_SHADER, vertex_source)
        fs = self._shader(GL_FRAGMENT_SHADER, fragment_source)
        prog = gl.glCreateProgram()
        gl.glAttachShader(prog, vs)
        gl.glAttachShader(prog, fs)
        gl.glLinkProgram(prog)
        ok = ctypes.c_int(0)
        gl.glGetProgramiv(prog, GL_LINK_STATUS, ctypes.byref(ok))
        if not ok.value:
            raise CompileError(self._log("glGetProgram", prog))
        gl.glFinish()
        for obj in (vs, fs):
            gl.glDeleteShader(obj)
        gl.glDeleteProgram(prog)
        return list(self.messages)


class CompileError(RuntimeError):
    pass


def group_by_stage(stats):
    """{stage: statistics} for each stage the driver printed (vertex, vertex_position and
    vertex_varying: Mali's two halves of an index-driven vertex shader, vertex_binning: Adreno's
    binning-pass vertex shader, fragment); a stage printed again (a recompile) goes to "other"."""
    out = {"other": []}
    for s in stats:
        if s["stage"] not in out:
            out[s["stage"]] = s
        else:
            out["other"].append(s)
    return out


def run_child(prefix, gpu, pairs):
    ctx = GlesContext(prefix)
    result = {"renderer": ctx.renderer, "version": ctx.version, "shaders": {}, "messages": {}}
    for pair in pairs:
        with open(pair["vertex"]) as f:
            vs = f.read()
        with open(pair["fragment"]) as f:
            fs = f.read()
        try:
            lines = ctx.compile_pair(vs, fs)
        except CompileError as e:
            sys.stderr.write("%s: error: %s does not compile on %s:\n%s\n" % (pair["fragment"], pair["name"], gpu, e))
            return 1, result
        stats = shaderdb.parse_messages(lines)
        if not stats:
            sys.stderr.write("error: %s on %s: the driver printed no statistics (messages: %r)\n"
                             % (pair["name"], gpu, lines))
            return 1, result
        result["shaders"][pair["name"]] = group_by_stage(stats)
        result["messages"][pair["name"]] = lines
    return 0, result


# --- the parent: one child process per GPU ---------------------------------------------------

def collect(prefix, gpus, pairs, disassembly=False):
    """{gpu: child result}; raises RuntimeError with the child's stderr on failure. disassembly:
    the compilers print their code, passed on to stderr."""
    out = {}
    for gpu in gpus:
        proc = subprocess.run([sys.executable, os.path.abspath(__file__), "--child", gpu, "--prefix", prefix],
                              input=json.dumps(pairs), capture_output=True, text=True,
                              env=child_environment(prefix, gpu, disassembly))
        if proc.returncode != 0:
            raise RuntimeError("compiling on %s failed (exit %d):\n%s" % (gpu, proc.returncode, proc.stderr))
        if disassembly:
            sys.stderr.write("=== %s\n%s" % (gpu, proc.stderr))
        out[gpu] = json.loads(proc.stdout)
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    add_gpu_arguments(ap)
    ap.add_argument("--vertex")
    ap.add_argument("--fragment")
    ap.add_argument("--package", help="a .matpkg: compile its own GLSL ES (read with matc info)")
    ap.add_argument("--variant", help="with --package: comma-separated variant keys (default: all)")
    ap.add_argument("--matc", default="matc", help="matc to read --package with (default: %(default)s)")
    ap.add_argument("--messages", action="store_true",
                    help="print the driver's debug messages as received (statistics fixtures), not JSON")
    ap.add_argument("--disassembly", action="store_true",
                    help="print each compiler's NIR and final code on stderr (the JSON is unchanged)")
    ap.add_argument("--child", help=argparse.SUPPRESS)
    ap.add_argument("pairs", nargs="?", help="JSON list of {name, vertex, fragment}")
    args = ap.parse_args(argv)

    if args.child:
        # A driver prints what its debug variables ask for on stdout: the result goes to a copy of
        # stdout taken first, and the driver's stdout is this process's stderr.
        result_out = os.fdopen(os.dup(1), "w")
        os.dup2(2, 1)
        code, result = run_child(args.prefix, args.child, json.load(sys.stdin))
        json.dump(result, result_out)
        result_out.close()
        return code

    if not (args.package or args.pairs or (args.vertex and args.fragment)):
        ap.error("give PAIRS.json, --vertex and --fragment, or --package")
    gpus = gpus_to_collect(args, "mesa_compile")
    if gpus is None:
        return EXIT_NOT_BUILT
    with tempfile.TemporaryDirectory(prefix="facet-mesa-compile-") as work:
        if args.package:
            variants = [v for v in args.variant.split(",") if v] if args.variant else None
            try:
                pairs, _ = package_glsl.package_pairs(args.matc, args.package, work, variants)
            except (RuntimeError, OSError, subprocess.CalledProcessError) as e:
                sys.stderr.write("mesa_compile: %s: error: %s\n" % (args.package, e))
                return 1
        elif args.pairs:
            with open(args.pairs) as f:
                pairs = json.load(f)
        else:
            pairs = [{"name": os.path.basename(args.fragment), "vertex": args.vertex, "fragment": args.fragment}]
        try:
            result = collect(args.prefix, gpus, pairs, args.disassembly)
        except RuntimeError as e:
            sys.stderr.write("mesa_compile: %s\n" % e)
            return 1
    if args.messages:
        for gpu in gpus:
            for pair in pairs:
                for line in result[gpu]["messages"][pair["name"]]:
                    sys.stdout.write(line.rstrip("\n") + "\n")
        return 0
    for gpu in gpus:
        del result[gpu]["messages"]
    json.dump({"gpus": result}, sys.stdout, indent=1, sort_keys=True)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
