#!/usr/bin/env python3
"""Checks the tools' JSON documents against docs/schema/rt.schema.json (JSON Schema 2020-12,
python3-jsonschema), and that docs/json.md names every field the schema holds.

  json_schema.py SCHEMA DEFINITION FILE...  each FILE is one document valid as #/$defs/DEFINITION
  json_schema.py --documented SCHEMA DOC    every property of SCHEMA appears in DOC as `name`

Prints one line per problem ("FILE: path: what is wrong") and exits 1 if there was any."""
import json
import re
import sys

import jsonschema


def no_duplicate_keys(pairs):
    keys = [k for k, _ in pairs]
    duplicates = {k for k in keys if keys.count(k) > 1}
    if duplicates:
        raise ValueError("duplicate keys: " + ", ".join(sorted(duplicates)))
    return dict(pairs)


def validate(schema_path, definition, files):
    schema = json.load(open(schema_path))
    jsonschema.Draft202012Validator.check_schema(schema)
    if definition not in schema["$defs"]:
        return [f"{schema_path}: no definition {definition}"]
    validator = jsonschema.Draft202012Validator({**schema, "$ref": "#/$defs/" + definition})
    problems = []
    for path in files:
        try:
            document = json.load(open(path), object_pairs_hook=no_duplicate_keys)
        except ValueError as e:
            problems.append(f"{path}: not JSON: {e}")
            continue
        for error in validator.iter_errors(document):
            where = "/".join(str(p) for p in error.absolute_path) or "(document)"
            problems.append(f"{path}: {where}: {error.message}")
    return problems


def property_names(node):
    if isinstance(node, dict):
        for key, value in node.items():
            if key == "properties":
                yield from value
            yield from property_names(value)
    elif isinstance(node, list):
        for item in node:
            yield from property_names(item)


def undocumented(schema_path, doc_path):
    documented = set(re.findall(r"`([A-Za-z]+)`", open(doc_path).read()))
    names = sorted(set(property_names(json.load(open(schema_path)))) - documented)
    return [f"{doc_path}: the field `{name}` of {schema_path} is not documented" for name in names]


if __name__ == "__main__":
    args = sys.argv[1:]
    problems = undocumented(*args[1:3]) if args[0] == "--documented" else validate(args[0], args[1], args[2:])
    for problem in problems:
        print("json_schema ERROR: " + problem, file=sys.stderr)
    sys.exit(1 if problems else 0)
