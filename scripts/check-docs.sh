#!/usr/bin/env bash
# Checks that the reference documentation and the source comments say what is true now and
# cite only what a reader of the repository has. Flags, as `file:line: what`:
#   - a date (YYYY-MM-DD): history belongs in docs/history/ or CHANGELOG.md;
#   - a commit hash: lower-case hex of 7-40 digits holding both a digit and a letter, standing
#     alone (not after 0x, #, a letter, a digit or _, so hex constants, colours and identifiers
#     are not hashes; all-digit runs such as the SPIR-V magic 07230203 are numbers; neither is
#     the offset column of an xxd dump);
#   - an issue-tracker reference (`issue 10`, `issue #10`, `(issue: hostile inputs)`,
#     "the issue's goal"): give the reason itself;
#   - a path outside the repository (`../shared`, `DESIGN.md`, `seeds/`, `/work/`).
# Looked at: README.md and docs/**/*.md (docs/history/ excepted: history keeps its dates and
# hashes), and only the comments of C/C++/GLSL, CMake, shell and Python sources (code, string
# literals and test data are not documentation). CHANGELOG.md is history and not looked at.
# Exit 0 when clean, 1 with the list, 2 on a usage error.
# Usage: scripts/check-docs.sh [FILE...]   (default: every file git tracks)
set -euo pipefail
caller=$PWD
cd "$(dirname "$0")/.."

exec env CHECK_DOCS_CALLER="$caller" python3 - "$@" <<'PY'
import io
import os
import re
import subprocess
import sys
import tokenize

RULES = [
    ("date", re.compile(r"(?<![0-9])(?:19|20)[0-9]{2}-[01][0-9]-[0-3][0-9](?![0-9])")),
    ("commit hash", re.compile(r"(?<![0-9A-Za-z_#\\])(?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])"
                               r"[0-9a-f]{7,40}(?![0-9A-Za-z_])")),
    ("issue reference", re.compile(r"\bissues?\s*#?\s*[0-9]+|\(\s*issue\s*:|\bthe issue's\b",
                                   re.IGNORECASE)),
    ("path outside the repository", re.compile(r"\.\./shared|\bDESIGN\.md|\bseeds/|(?<![\w.])/work/")),
]

# A hex dump's offset column (`00000040: f000 ...`, as xxd prints it) is not a hash.
XXD_OFFSET = re.compile(r"^[0-9a-f]{8}: ")

C_LIKE = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".inl",
          ".glsl", ".vert", ".frag", ".comp")
HASH_LIKE = (".cmake", ".cmake.in", ".sh")


def is_history(path):
    return path.startswith("docs/history/") or path == "CHANGELOG.md"


# This script names every pattern it looks for, so it does not look at itself.
SELF = "scripts/check-docs.sh"


def kind_of(path):
    name = os.path.basename(path)
    if is_history(path) or path == SELF:
        return None
    if path == "README.md" or (path.startswith("docs/") and path.endswith(".md")):
        return "text"
    if path.endswith(C_LIKE):
        return "c"
    if name == "CMakeLists.txt" or path.endswith(HASH_LIKE) or path == ".ci/run":
        return "hash"
    if path.endswith(".py"):
        return "python"
    return None


def c_comments(text):
    """(line, comment text) of // and /* */ comments, skipping string and character literals."""
    out = []
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            out.append((line, text[i:end]))
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            for k, part in enumerate(text[i:end].split("\n")):
                out.append((line + k, part))
            line += text.count("\n", i, end)
            i = end
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not text[i - 1].isalnum()):
            m = re.match(r'R"([^(\s]*)\(', text[i:])
            if not m:
                i += 1
                continue
            close = ")" + m.group(1) + '"'
            end = text.find(close, i + m.end())
            end = n if end < 0 else end + len(close)
            line += text.count("\n", i, end)
            i = end
        elif c == '"' or (c == "'" and (i == 0 or not text[i - 1].isalnum())):
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        else:
            i += 1
    return out


def hash_comments(text):
    """(line, comment text) of # comments in shell and CMake, skipping quoted strings."""
    out = []
    for number, raw in enumerate(text.split("\n"), 1):
        quote = None
        for k, c in enumerate(raw):
            if quote:
                if c == "\\" and quote == '"':
                    continue
                if c == quote:
                    quote = None
            elif c in "'\"":
                quote = c
            elif c == "#" and (k == 0 or raw[k - 1] in " \t;(") and not raw.startswith("#!"):
                out.append((number, raw[k:]))
                break
    return out


def python_comments(text):
    """(line, text) of # comments and of triple-quoted strings (docstrings)."""
    out = []
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT:
                out.append((tok.start[0], tok.string))
            elif tok.type == tokenize.STRING and re.match(r'^[rRbBuUfF]*("""|\'\'\')', tok.string):
                for k, part in enumerate(tok.string.split("\n")):
                    out.append((tok.start[0] + k, part))
    except (tokenize.TokenError, SyntaxError):
        out = hash_comments(text)
    return out


def lines_to_check(path, kind, text):
    if kind == "text":
        return list(enumerate(text.split("\n"), 1))
    if kind == "c":
        return c_comments(text)
    if kind == "hash":
        return hash_comments(text)
    return python_comments(text)


def main(argv):
    if any(a.startswith("-") for a in argv):
        print("usage: scripts/check-docs.sh [FILE...]", file=sys.stderr)
        return 2
    if argv:
        caller = os.environ.get("CHECK_DOCS_CALLER", os.getcwd())
        files = [os.path.relpath(os.path.join(caller, a)) for a in argv]
    else:
        files = subprocess.run(["git", "ls-files"], check=True, capture_output=True,
                               text=True).stdout.split("\n")
    findings = 0
    for path in files:
        kind = kind_of(path)
        if not kind or not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        for number, line in lines_to_check(path, kind, text):
            for what, rule in RULES:
                for m in rule.finditer(line):
                    if what == "commit hash" and XXD_OFFSET.match(line) and m.start() == 0:
                        continue
                    print(f"{path}:{number}: {what}: {m.group(0)!r}")
                    findings += 1
    if findings:
        print(f"check-docs: {findings} finding(s): move history to docs/history/ or CHANGELOG.md, "
              "give reasons instead of issue numbers, cite the repository's own docs",
              file=sys.stderr)
        return 1
    return 0


sys.exit(main(sys.argv[1:]))
PY
