#!/usr/bin/python3
"""Validates a SARIF log against the published SARIF 2.1.0 JSON schema (Debian's python3-jsonschema).

usage: validate_sarif.py SCHEMA LOG [MIN_RESULTS]
The schema comes from the npm package @microsoft/jest-sarif (scripts/setup-deps.sh installs it).
"""
import json
import sys

import jsonschema


def main() -> int:
    schema_path, log_path = sys.argv[1], sys.argv[2]
    min_results = int(sys.argv[3]) if len(sys.argv) > 3 else 0
    try:
        with open(schema_path, encoding="utf-8") as f:
            schema = json.load(f)
    except OSError as e:
        print(f"error: cannot read the SARIF schema {schema_path} ({e.strerror}); run scripts/setup-deps.sh")
        return 1
    with open(log_path, encoding="utf-8") as f:
        log = json.load(f)
    validator = jsonschema.Draft4Validator(schema)
    errors = sorted(validator.iter_errors(log), key=lambda e: list(e.path))
    for e in errors:
        print(f"{log_path}: /{'/'.join(str(p) for p in e.path)}: {e.message}")
    results = sum(len(run.get("results", [])) for run in log.get("runs", []))
    if results < min_results:
        print(f"{log_path}: {results} results, expected at least {min_results}")
        return 1
    print(f"{log_path}: valid SARIF 2.1.0, {results} results")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
