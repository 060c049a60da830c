#!/bin/sh
# lint_sarif_schema MATC MATERIAL OUT SCHEMA: matc lint's SARIF report of a material with known
# findings exits 1 (it has an error) and validates against the SARIF 2.1.0 schema.
matc=$1 material=$2 out=$3 schema=$4
"$matc" lint "$material" --format sarif -o "$out"
status=$?
if [ "$status" -ne 1 ]; then
  echo "matc lint exited $status, expected 1 (the material has an error)"
  exit 1
fi
exec /usr/bin/python3 "$(dirname "$0")/validate_sarif.py" "$schema" "$out" 5
