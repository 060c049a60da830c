#!/usr/bin/env bash
# git's textconv for the MSL goldens (tests/golden/shaders/**/*.metal, see .gitattributes): the
# file with SPIRV-Cross's temporaries, named after their SPIR-V ids (_761), shown as _N. One id
# added early in a module renumbers every later one, so the raw diff of a one-constant chunk change
# rewrites the whole function; masked, it shows the expressions that changed. The files stay the
# shipped bytes: this changes what `git diff` shows, once enabled in a clone (docs/testing.md):
#   git config diff.facet-msl.textconv scripts/msl-diff-text.sh
set -euo pipefail
exec sed -E 's/\b_[0-9]+\b/_N/g' "$1"
