#!/usr/bin/python3
"""Validates JSON documents against a JSON schema (draft 7) with Debian's python3-jsonschema.

usage: validate_json.py SCHEMA FILE... ; exit 0 when every file holds one valid document,
1 otherwise, 77 (skipped) when jsonschema is not installed.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(77)

schema = json.load(open(sys.argv[1]))
jsonschema.Draft7Validator.check_schema(schema)
validator = jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())
bad = 0
for path in sys.argv[2:]:
    try:
        doc = json.load(open(path))  # one document, nothing before or after it
    except ValueError as e:
        print(f"{path}: not one JSON document: {e}")
        bad += 1
        continue
    errors = sorted(validator.iter_errors(doc), key=lambda e: list(e.path))
    for e in errors:
        print(f"{path}: {'/'.join(map(str, e.path))}: {e.message}")
    bad += bool(errors)
print(f"{len(sys.argv) - 2} documents, {bad} invalid")
sys.exit(1 if bad else 0)
