#!/usr/bin/python3
"""Validates SARIF logs against a JSON schema with Debian's python3-jsonschema.

usage: validate_sarif.py SCHEMA LOG... ; exit 0 when every log is valid, 1 otherwise,
77 (skipped) when jsonschema is not installed.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(77)

schema = json.load(open(sys.argv[1]))
validator = jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())
bad = 0
for path in sys.argv[2:]:
    log = json.load(open(path))
    errors = sorted(validator.iter_errors(log), key=lambda e: list(e.path))
    for e in errors:
        print(f"{path}: {'/'.join(map(str, e.path))}: {e.message}")
    bad += bool(errors)
    if not log["runs"][0].get("results"):
        print(f"{path}: no results: nothing was validated")
        bad += 1
sys.exit(1 if bad else 0)
