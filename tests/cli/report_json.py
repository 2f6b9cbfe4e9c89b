#!/usr/bin/python3
"""Reads MeshBridge JSON output for the CLI tests; every object is validated against
docs/report-schema.json first, so a malformed or off-schema output fails the test.

  report_json.py validate FILE          FILE holds one JSON object
  report_json.py validate-lines FILE    FILE holds JSON Lines (one object per line, >= 1 line)
  report_json.py get FILE KEY.PATH      prints the value at KEY.PATH (validated first); lists
                                        print their length with KEY.PATH#, JSON values as JSON
  report_json.py get-line FILE N KEY.PATH   the same on line N (0-based) of a JSON Lines file
"""
import json
import os
import sys

import jsonschema

SCHEMA_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs",
                           "report-schema.json")


def fail(message):
    print("report_json.py: " + message, file=sys.stderr)
    sys.exit(1)


def validator():
    with open(SCHEMA_PATH, encoding="utf-8") as handle:
        return jsonschema.Draft7Validator(json.load(handle))


def parse(text, where):
    try:
        return json.loads(text)
    except ValueError as error:
        fail("%s is not valid JSON: %s: %r" % (where, error, text[:300]))


def validated(obj, where):
    errors = sorted(validator().iter_errors(obj), key=lambda e: list(e.path))
    if errors:
        fail("%s does not match docs/report-schema.json: %s" % (where, "; ".join(
            "%s: %s" % ("/".join(map(str, e.path)), e.message[:300]) for e in errors[:5])))
    return obj


def read_bytes(path):
    with open(path, "rb") as handle:
        data = handle.read()
    try:
        return data.decode("utf-8")  # strict: the output must be valid UTF-8
    except UnicodeDecodeError as error:
        fail("%s is not valid UTF-8: %s" % (path, error))


def one(path):
    return validated(parse(read_bytes(path), path), path)


def lines(path):
    text = read_bytes(path)
    if not text.endswith("\n"):
        fail("%s: JSON Lines output must end with a newline" % path)
    rows = text[:-1].split("\n")
    if rows == [""]:
        fail("%s: no JSON line" % path)
    return [validated(parse(row, "%s line %d" % (path, i)), "%s line %d" % (path, i))
            for i, row in enumerate(rows)]


def get(obj, key_path):
    length = key_path.endswith("#")
    value = obj
    for key in key_path.rstrip("#").split("."):
        if isinstance(value, list):
            value = value[int(key)]
        elif isinstance(value, dict) and key in value:
            value = value[key]
        else:
            fail("no key %s (in %s)" % (key_path, json.dumps(obj)[:300]))
    if length:
        return str(len(value))
    if isinstance(value, bool):
        return "true" if value else "false"
    return value if isinstance(value, str) else json.dumps(value, separators=(",", ":"))


def main(argv):
    if len(argv) >= 2 and argv[0] == "validate":
        one(argv[1])
    elif len(argv) >= 2 and argv[0] == "validate-lines":
        print(len(lines(argv[1])))
    elif len(argv) == 3 and argv[0] == "get":
        print(get(one(argv[1]), argv[2]))
    elif len(argv) == 4 and argv[0] == "get-line":
        print(get(lines(argv[1])[int(argv[2])], argv[3]))
    else:
        fail("usage: see the docstring")


if __name__ == "__main__":
    main(sys.argv[1:])
