#!/usr/bin/env python3
"""Checks that docs/orb-scene.schema.json and Orb's scene loader agree.

valid/            both accept
invalid-schema/   both reject
invalid-semantic/ the schema accepts (it cannot express the rule), the loader rejects
Every Orb JSON scene shipped in scenes/ must be accepted by both, and every
scene the loader writes must validate against the schema.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("schema_agreement.py: python3-jsonschema is required (apt-get install python3-jsonschema)")


def loader_accepts(checker, path, rewritten=None):
    command = [checker, str(path)] + ([str(rewritten)] if rewritten else [])
    result = subprocess.run(command, capture_output=True, text=True, timeout=60)
    if result.returncode not in (0, 1):
        sys.exit(f"{path}: scene_check failed with exit {result.returncode}: {result.stderr}")
    return result.returncode == 0, result.stderr.strip()


def schema_accepts(validator, path):
    try:
        document = json.loads(path.read_text())
    except ValueError as e:
        return False, str(e)
    errors = sorted(validator.iter_errors(document), key=lambda e: e.path)
    return not errors, "; ".join(e.message for e in errors[:3])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--schema", required=True)
    parser.add_argument("--checker", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--scenes", required=True)
    args = parser.parse_args()

    schema = json.loads(pathlib.Path(args.schema).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)

    data = pathlib.Path(args.data)
    expectations = {"valid": (True, True), "invalid-schema": (False, False), "invalid-semantic": (True, False)}
    cases = [(p, expectations[d]) for d in expectations for p in sorted((data / d).glob("*.json"))]
    cases += [(p, (True, True)) for p in sorted(pathlib.Path(args.scenes).glob("*.json"))]
    if len(cases) < 10:
        sys.exit(f"only {len(cases)} cases found under {data}: the test data is missing")

    passed = failed = 0
    for path, (schema_expected, loader_expected) in cases:
        schema_ok, schema_why = schema_accepts(validator, path)
        rewritten = pathlib.Path(tempfile.mkdtemp()) / "rewritten.json"
        loader_ok, loader_why = loader_accepts(args.checker, path, rewritten)
        if loader_ok:
            written_ok, written_why = schema_accepts(validator, rewritten)
            if not written_ok:
                schema_ok, schema_why = False, "the loader's own output fails the schema: " + written_why
        if schema_ok == schema_expected and loader_ok == loader_expected:
            passed += 1
        else:
            failed += 1
            print(f"FAIL {path}: schema {'accepts' if schema_ok else 'rejects'} ({schema_why}), "
                  f"loader {'accepts' if loader_ok else 'rejects'} ({loader_why})")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
