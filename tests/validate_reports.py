#!/usr/bin/env python3
"""Validates render reports (`ontile render --report`) against docs/report.schema.json.
Usage: validate_reports.py SCHEMA REPORT... ; exit 1 when any report does not match."""
import json
import pathlib
import sys

import jsonschema


def main() -> int:
    schema_path = pathlib.Path(sys.argv[1])
    schema = json.loads(schema_path.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = 0
    for report in map(pathlib.Path, sys.argv[2:]):
        errors = sorted(validator.iter_errors(json.loads(report.read_text())), key=lambda e: list(e.path))
        for error in errors[:5]:
            print(f"{report}: {'/'.join(map(str, error.path)) or '(root)'}: {error.message}")
        failures += bool(errors)
    return 1 if failures or len(sys.argv) < 3 else 0


if __name__ == "__main__":
    sys.exit(main())
