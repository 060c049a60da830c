#!/usr/bin/env python3
"""tools/filament/extract_glsl.py on a package Filament's own matc (Debian libfilament-tools
1.9.25, /usr/bin/matc, installed by scripts/setup-deps.sh) compiles from
tools/filament/red_plastic.mat: the shader list, the sun variant's GLSL ES, which glslang
accepts, and one-line errors on damaged files. Skipped (77) where Filament's matc is absent."""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
EXTRACT = os.path.join(ROOT, "tools", "filament", "extract_glsl.py")
FILAMENT_MATC = "/usr/bin/matc"


def run(*args):
    return subprocess.run([sys.executable, EXTRACT, *args], capture_output=True, text=True)


class ExtractGlsl(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="facet-filamat-")
        cls.package = os.path.join(cls.dir, "red.filamat")
        subprocess.run([FILAMENT_MATC, "-p", "mobile", "-a", "opengl", "-o", cls.package,
                        os.path.join(ROOT, "tools", "filament", "red_plastic.mat")], check=True,
                       capture_output=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_list_names_the_sun_variant(self):
        r = run(self.package, "--list")
        self.assertEqual(r.returncode, 0, r.stderr)
        sun = [l for l in r.stdout.splitlines() if "1 (0x01)" in l and "fragment" in l]
        self.assertEqual(len(sun), 1, r.stdout)
        self.assertIn("DIR", sun[0])

    def test_sun_fragment_is_glsl_es_that_glslang_accepts(self):
        out = os.path.join(self.dir, "sun.frag")
        r = run(self.package, "--variant", "1", "--stage", "fragment", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out) as f:
            self.assertEqual(f.readline().strip(), "#version 300 es")
        check = subprocess.run(["glslangValidator", "-S", "frag", out], capture_output=True, text=True)
        self.assertEqual(check.returncode, 0, check.stdout)

    def test_damaged_files_get_one_line_errors(self):
        with open(self.package, "rb") as f:
            data = f.read()
        for name, blob in (("truncated", data[: len(data) // 2]), ("empty", b""), ("text", b"material {}\n")):
            path = os.path.join(self.dir, name + ".filamat")
            with open(path, "wb") as f:
                f.write(blob)
            r = run(path, "--list")
            self.assertEqual(r.returncode, 1, name)
            self.assertNotIn("Traceback", r.stderr, name)
            self.assertIn("error:", r.stderr, name)


if __name__ == "__main__":
    if not os.path.exists(FILAMENT_MATC):
        print("Filament's matc is not installed (apt-get install libfilament-tools): skipped")
        sys.exit(77)
    unittest.main()
