#!/usr/bin/env python3
"""Validates JSON files against a JSON Schema (draft-07) with python3-jsonschema (Debian).

usage: validate_json_schema.py SCHEMA [--expect-invalid] FILE...

Checks the schema itself against the draft-07 meta-schema first. Prints one line per file,
"FILE: valid" or "FILE: invalid: <the most relevant error>", and exits 0 when every file is
as expected (valid, or with --expect-invalid, invalid), 1 when not, 3 when jsonschema is missing.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed: run scripts/setup.sh (apt-get install python3-jsonschema)")
    sys.exit(3)


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    schema_path = argv[1]
    expect_invalid = "--expect-invalid" in argv[2:]
    files = [a for a in argv[2:] if a != "--expect-invalid"]
    with open(schema_path, encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    unexpected = 0
    for path in files:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
        error = jsonschema.exceptions.best_match(validator.iter_errors(doc))
        if error is None:
            print(f"{path}: valid")
            unexpected += expect_invalid
        else:
            where = "/".join(str(p) for p in error.absolute_path)
            print(f"{path}: invalid: at /{where}: {error.message}")
            unexpected += not expect_invalid
    return 1 if unexpected else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
