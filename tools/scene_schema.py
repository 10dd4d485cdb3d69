#!/usr/bin/env python3
"""The scene schema's documents, generated from what the programs print with `--schema`.

`fluid_app --schema` and `dem_app --schema` print the schema the scene readers read every key
through (coupler_lib/scene/schema.hpp). From it this tool writes

  docs/scene-reference.md   one section per mapping of a scene: keys, types, units, defaults,
                            allowed values, meaning
  docs/scene.schema.json    a JSON Schema (draft-07) for editors: the YAML language server
                            completes, documents and checks a scene that starts with
                            `# yaml-language-server: $schema=<path to docs/scene.schema.json>`

and checks scenes against the JSON Schema. Usage (with /usr/bin/python3):

  scene_schema.py generate --app build/fluid_app/fluid_app [--docs docs] [--check [--out DIR]]
      writes both documents into --docs; with --check compares them with the committed ones
      instead (writing the fresh copies into --out) and fails when they differ
  scene_schema.py validate docs/scene.schema.json scene.yaml|folder ... [--exclude FOLDER]
      checks every scene (a folder: every *.yaml below it) against the JSON Schema
  scene_schema.py same fluid_app dem_app
      fails unless both programs print the same schema

The validator below implements the part of JSON Schema draft-07 that the generated schema uses
and refuses any other keyword, so that the check never passes by ignoring a rule; where the
`jsonschema` package is installed (Debian: python3-jsonschema) the scenes are checked with it
as well.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

import yaml

SCHEMA_URI = "http://json-schema.org/draft-07/schema#"


# --------------------------------------------------------------------------------------------
# Reading the programs' schema


def read_schema(app):
    out = subprocess.run([app, "--schema"], check=True, capture_output=True, text=True).stdout
    schema = json.loads(out)
    if schema.get("format") != "lbdem-scene-schema" or schema.get("version") != 1:
        raise SystemExit(f"{app} --schema: not an lbdem-scene-schema version 1")
    return schema


def mappings_by_path(schema):
    return {m["path"]: m for m in schema["mappings"]}


# --------------------------------------------------------------------------------------------
# docs/scene-reference.md


def title(path):
    return "top level" if path == "" else f"`{path}`"


def anchor(path):
    # GitHub's heading anchors: lower case, punctuation other than - and _ dropped.
    return re.sub(r"[^a-z0-9 _-]", "", title(path).lower()).replace(" ", "-")


def number_text(v):
    if isinstance(v, float) and v.is_integer() and abs(v) < 1e15:
        return str(int(v))
    return repr(v) if isinstance(v, float) else str(v)


def value_text(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return number_text(v)
    if isinstance(v, list):
        return "[" + ", ".join(value_text(x) for x in v) + "]"
    if v == "":
        return '`""`'
    return f"`{v}`"


def bounds_text(k):
    lo = k.get("minimum", k.get("exclusive_minimum"))
    hi = k.get("maximum", k.get("exclusive_maximum"))
    lo_open = "exclusive_minimum" in k
    hi_open = "exclusive_maximum" in k
    if lo is not None and hi is not None:
        if lo == hi and not lo_open and not hi_open:
            return f"= {number_text(lo)}"
        return f"{'(' if lo_open else '['}{number_text(lo)}, {number_text(hi)}{')' if hi_open else ']'}"
    if lo is not None:
        return f"{'>' if lo_open else '≥'} {number_text(lo)}"
    if hi is not None:
        return f"{'<' if hi_open else '≤'} {number_text(hi)}"
    return ""


def type_text(k):
    t = k["type"]
    if t == "vector":
        return f"{k['size']} numbers"
    if t == "choice":
        return "word or mapping" if "mapping" in k else "word"
    if t == "section":
        return "mapping"
    if t == "list":
        return "list of mappings"
    return t


def allowed_text(k):
    parts = []
    if k.get("values"):
        parts.append(", ".join(f"`{v}`" for v in k["values"]))
    b = bounds_text(k)
    if b:
        parts.append(("each " if k["type"] == "vector" else "") + b)
    if "mapping" in k:
        parts.append(f"see [{title(k['mapping'])}](#{anchor(k['mapping'])})")
    return "; ".join(parts)


def default_text(k):
    need = k["need"]
    if need == "required":
        return "**required**"
    if need == "defaulted":
        return value_text(k["default"])
    if need == "derived":
        return f"*derived:* {k['rule']}"
    return f"*absent:* {k['rule']}"


def cell(text):
    # Outside code spans a `<name>` would be read as an HTML tag and vanish.
    parts = text.replace("|", "\\|").replace("\n", " ").split("`")
    return "`".join(p if i % 2 else p.replace("<", "&lt;") for i, p in enumerate(parts))


def key_table(keys):
    rows = ["| key | type | unit | default | allowed | meaning |", "|---|---|---|---|---|---|"]
    for k in keys:
        rows.append("| " + " | ".join(cell(x) for x in (
            f"`{k['name']}`", type_text(k), k.get("unit", ""), default_text(k), allowed_text(k),
            k["meaning"])) + " |")
    return "\n".join(rows) + "\n"


def groups_text(m):
    lines = []
    for g in m["exactly_one_of"]:
        lines.append("Exactly one of " + ", ".join(f"`{n}`" for n in g) + " must be given.")
    for g in m["at_least_one_of"]:
        lines.append("At least one of " + ", ".join(f"`{n}`" for n in g) + " must be given.")
    return lines


def alternative_title(a, m):
    if a["key"] == "":
        others = [f"`{b['key']}`" for b in m["alternatives"] if b["key"]]
        return "Otherwise (no " + " and no ".join(others) + ")"
    if a["value"] == "":
        return f"With `{a['key']}`"
    return f"With `{a['key']}: {a['value']}`"


def reference_markdown(schema):
    out = [
        "# Scene reference",
        "",
        "Generated by `tools/scene_schema.py` from `fluid_app --schema` (`dem_app --schema` prints",
        "the same): the schema the programs read every scene key through",
        "(`coupler_lib/scene/*_section.cpp`, docs/developer.md \"Adding a scene key\"). ctest",
        "`docs_scene_schema` fails when this page or [scene.schema.json](scene.schema.json) differ",
        "from it; regenerate both with",
        "`/usr/bin/python3 tools/scene_schema.py generate --app build/fluid_app/fluid_app`.",
        "See [user-guide.md](user-guide.md) for what each section does and for editor set-up.",
        "",
        "**Default**: the value the programs use when the key is left out; **required**: the key",
        "must be given; *derived*: the default follows from other keys as described; *absent*: what",
        "leaving the key out means. **Allowed**: the words a key accepts, or the range of a number",
        "(`[a, b]` closed, `(a, b)` open). A list's entries are described under `name[]`. Units are",
        "SI; a number without a unit is dimensionless (or a count).",
    ]
    for m in schema["mappings"]:
        out += ["", f"## {title(m['path'])}", "", m["meaning"][0].upper() + m["meaning"][1:] + "."]
        if m["keys"]:
            out += ["", key_table(m["keys"]).rstrip("\n")]
        groups = groups_text(m)
        if groups:
            out += [""] + groups
        for a in m["alternatives"]:
            out += ["", f"{alternative_title(a, m)}:", ""]
            out.append(key_table(a["keys"]).rstrip("\n"))
            groups = [("Exactly one of " + ", ".join(f"`{n}`" for n in g) + " must be given.")
                      for g in a["exactly_one_of"]]
            if groups:
                out += [""] + groups
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------------------------
# docs/scene.schema.json


def definition_name(path):
    return "scene" if path == "" else path.replace("[]", "_entry").replace("<", "").replace(">", "")


def ref(path):
    return {"$ref": "#/definitions/" + definition_name(path)}


def description(k):
    text = k["meaning"]
    unit = k.get("unit")
    if unit and not any(f in text for f in (f"in {unit}", f"({unit})", f", {unit}")):
        text += f" [{unit}]"
    if k["need"] == "required":
        text += " (required)"
    elif k["need"] == "derived":
        text += f" (default: {k['rule']})"
    elif k["need"] == "optional":
        text += f" (absent: {k['rule']})"
    return text


def number_rules(k):
    rules = {}
    for ours, theirs in (("minimum", "minimum"), ("exclusive_minimum", "exclusiveMinimum"),
                         ("maximum", "maximum"), ("exclusive_maximum", "exclusiveMaximum")):
        if ours in k:
            rules[theirs] = k[ours]
    return rules


def key_schema(k):
    t = k["type"]
    if t in ("number", "integer"):
        s = {"type": t, **number_rules(k)}
    elif t == "boolean":
        s = {"type": "boolean"}
    elif t == "string":
        s = {"type": "string"}
    elif t == "choice":
        s = {"type": "string", "enum": k["values"]}
        if "mapping" in k:
            s = {"anyOf": [s, ref(k["mapping"])]}
    elif t == "vector":
        s = {"type": "array", "items": {"type": "number", **number_rules(k)},
             "minItems": k["size"], "maxItems": k["size"]}
    elif t == "section":
        s = {"allOf": [ref(k["mapping"])]}
    elif t == "list":
        s = {"type": "array", "items": ref(k["mapping"])}
    else:
        raise SystemExit(f"scene_schema.py: unknown key type '{t}'")
    s["description"] = description(k)
    if k["need"] == "defaulted":
        s["default"] = k["default"]
    return s


def alternative_condition(a):
    if a["key"] == "":
        return None
    if a["value"] == "":
        return {"required": [a["key"]]}
    return {"required": [a["key"]], "properties": {a["key"]: {"const": a["value"]}}}


def exactly_one(group):
    return {"oneOf": [{"required": [n]} for n in group]}


def mapping_schema(m):
    common = {k["name"] for k in m["keys"]}
    properties = {k["name"]: key_schema(k) for k in m["keys"]}
    # A key of alternatives is listed at the top (so that it is known, and an editor offers it)
    # with what all its alternatives agree on; each alternative allows its own keys with their
    # full rules and forbids the other alternatives' keys.
    alternative_keys = {}
    for a in m["alternatives"]:
        for k in a["keys"]:
            if k["name"] not in common:
                alternative_keys.setdefault(k["name"], []).append((a, key_schema(k)))
    for name, uses in alternative_keys.items():
        def rules(s):
            return {r: v for r, v in s.items() if r != "description"}
        first = rules(uses[0][1])
        top = dict(first) if all(rules(s) == first for _, s in uses) else {}
        top["description"] = "; ".join(f"{alternative_title(a, m)}: {s['description']}"
                                       for a, s in uses)
        properties[name] = top
    s = {"type": "object", "description": m["meaning"], "properties": properties,
         "additionalProperties": False}
    required = [k["name"] for k in m["keys"] if k["need"] == "required"]
    if required:
        s["required"] = required
    rules = [exactly_one(g) for g in m["exactly_one_of"]]
    rules += [{"anyOf": [{"required": [n]} for n in g]} for g in m["at_least_one_of"]]
    earlier = []
    for a in m["alternatives"]:
        cond = alternative_condition(a)
        applies = cond if cond is not None else {}
        if earlier:
            applies = {"allOf": ([cond] if cond else []) + [{"not": {"anyOf": list(earlier)}}]}
        own = {k["name"] for k in a["keys"]}
        then = {"properties": {k["name"]: key_schema(k) for k in a["keys"]}}
        for name in alternative_keys:
            if name not in own:
                then["properties"][name] = False
        a_required = [k["name"] for k in a["keys"] if k["need"] == "required"]
        if a_required:
            then["required"] = a_required
        if a["exactly_one_of"]:
            then["allOf"] = [exactly_one(g) for g in a["exactly_one_of"]]
        rules.append({"if": applies, "then": then})
        if cond is not None:
            earlier.append(cond)
    if rules:
        s["allOf"] = rules
    return s


def json_schema(schema):
    by_path = mappings_by_path(schema)
    root = mapping_schema(by_path[schema["root"]])
    out = {
        "$schema": SCHEMA_URI,
        "title": "lbdem scene",
        "$comment": "Generated by tools/scene_schema.py from `fluid_app --schema`; do not edit "
                    "(docs/scene-reference.md lists the same keys).",
    }
    out.update(root)
    out["definitions"] = {definition_name(m["path"]): mapping_schema(m)
                          for m in schema["mappings"] if m["path"] != schema["root"]}
    return json.dumps(out, indent=1, ensure_ascii=False) + "\n"


# --------------------------------------------------------------------------------------------
# Checking scenes


class Loader(yaml.SafeLoader):
    """YAML as the programs read it (yaml-cpp, YAML 1.2): `1e-6` is a number, not a string."""


Loader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"""^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?
                |[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$""", re.X),
    list("-+0123456789."))


def load_scene(path):
    with open(path) as f:
        return yaml.load(f, Loader=Loader)


KNOWN = {"$schema", "$comment", "$ref", "title", "description", "default", "definitions", "type",
         "enum", "const", "properties", "additionalProperties", "required", "items", "minItems",
         "maxItems", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum", "allOf",
         "anyOf", "oneOf", "not", "if", "then", "else"}


def type_ok(value, t):
    if t == "object":
        return isinstance(value, dict)
    if t == "array":
        return isinstance(value, list)
    if t == "string":
        return isinstance(value, str)
    if t == "boolean":
        return isinstance(value, bool)
    if t == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if t == "integer":
        return (isinstance(value, int) and not isinstance(value, bool)) or (
            isinstance(value, float) and math.isfinite(value) and value.is_integer())
    raise SystemExit(f"scene_schema.py: type '{t}' is not supported by the validator")


def where(path):
    return "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in path).lstrip(".") or "<top>"


def errors(schema, value, root, path=()):
    """The list of rule violations of `value` (messages naming the key)."""
    if schema is True:
        return []
    if schema is False:
        return [f"{where(path)}: not allowed here"]
    unknown = set(schema) - KNOWN
    if unknown:
        raise SystemExit(f"scene_schema.py: the validator does not know {sorted(unknown)}")
    if "$ref" in schema:
        target = root
        for part in schema["$ref"].lstrip("#/").split("/"):
            target = target[part]
        return errors(target, value, root, path)
    out = []
    if "type" in schema and not type_ok(value, schema["type"]):
        return [f"{where(path)}: expected {schema['type']}, got {value!r}"]
    if "enum" in schema and value not in schema["enum"]:
        out.append(f"{where(path)}: expected one of {schema['enum']}, got {value!r}")
    if "const" in schema and value != schema["const"]:
        out.append(f"{where(path)}: expected {schema['const']!r}")
    if type_ok(value, "number"):
        for rule, bad in (("minimum", lambda v, b: v < b), ("maximum", lambda v, b: v > b),
                          ("exclusiveMinimum", lambda v, b: v <= b),
                          ("exclusiveMaximum", lambda v, b: v >= b)):
            if rule in schema and bad(value, schema[rule]):
                out.append(f"{where(path)}: {value} violates {rule} {schema[rule]}")
    if isinstance(value, list):
        if "minItems" in schema and len(value) < schema["minItems"]:
            out.append(f"{where(path)}: needs at least {schema['minItems']} entries")
        if "maxItems" in schema and len(value) > schema["maxItems"]:
            out.append(f"{where(path)}: takes at most {schema['maxItems']} entries")
        if "items" in schema:
            for i, v in enumerate(value):
                out += errors(schema["items"], v, root, path + (i,))
    if isinstance(value, dict):
        props = schema.get("properties", {})
        for name in schema.get("required", []):
            if name not in value:
                out.append(f"{where(path)}: missing required key '{name}'")
        for name, v in value.items():
            if name in props:
                out += errors(props[name], v, root, path + (name,))
            elif schema.get("additionalProperties", True) is False:
                out.append(f"{where(path + (name,))}: unknown key")
    for sub in schema.get("allOf", []):
        out += errors(sub, value, root, path)
    if "anyOf" in schema and all(errors(s, value, root, path) for s in schema["anyOf"]):
        out.append(f"{where(path)}: matches none of the allowed forms")
    if "oneOf" in schema:
        n = sum(not errors(s, value, root, path) for s in schema["oneOf"])
        if n != 1:
            out.append(f"{where(path)}: must match exactly one of {len(schema['oneOf'])} forms "
                       f"(matches {n})")
    if "not" in schema and not errors(schema["not"], value, root, path):
        out.append(f"{where(path)}: matches a form that is not allowed")
    if "if" in schema:
        if not errors(schema["if"], value, root, path):
            out += errors(schema.get("then", True), value, root, path)
        else:
            out += errors(schema.get("else", True), value, root, path)
    return out


def scene_files(paths, exclude=()):
    skip = [os.path.abspath(e) for e in exclude]
    for p in paths:
        if os.path.isdir(p):
            for folder, subs, files in os.walk(p):
                subs[:] = sorted(d for d in subs
                                 if os.path.abspath(os.path.join(folder, d)) not in skip)
                for name in sorted(files):
                    if name.endswith(".yaml"):
                        yield os.path.join(folder, name)
        else:
            yield p


def validate(schema_file, paths, exclude=()):
    with open(schema_file) as f:
        schema = json.load(f)
    try:
        import jsonschema
    except ImportError:
        jsonschema = None
    if jsonschema is not None:
        jsonschema.Draft7Validator.check_schema(schema)
    failed = 0
    files = list(scene_files(paths, exclude))
    if not files:
        raise SystemExit("scene_schema.py: no scenes to check")
    for path in files:
        try:
            scene = load_scene(path)
        except (yaml.YAMLError, UnicodeDecodeError) as e:
            failed += 1
            print(f"{path}: not YAML: {e}", file=sys.stderr)
            continue
        found = errors(schema, scene, schema)
        if jsonschema is not None:
            theirs = sorted(jsonschema.Draft7Validator(schema).iter_errors(scene), key=str)
            if bool(theirs) != bool(found):
                found.append("the validators disagree: jsonschema says " +
                             ("; ".join(e.message for e in theirs) or "valid"))
        if found:
            failed += 1
            print(f"{path}:", file=sys.stderr)
            for e in found:
                print(f"  {e}", file=sys.stderr)
    print(f"{len(files) - failed} of {len(files)} scenes match {schema_file}"
          + (" (also checked with jsonschema)" if jsonschema else ""))
    return 1 if failed else 0


# --------------------------------------------------------------------------------------------


def generate(args):
    schema = read_schema(args.app)
    documents = {"scene-reference.md": reference_markdown(schema),
                 "scene.schema.json": json_schema(schema)}
    if not args.check:
        for name, text in documents.items():
            with open(os.path.join(args.docs, name), "w") as f:
                f.write(text)
        print(f"wrote {', '.join(documents)} into {args.docs}")
        return 0
    stale = []
    for name, text in documents.items():
        if args.out:
            os.makedirs(args.out, exist_ok=True)
            with open(os.path.join(args.out, name), "w") as f:
                f.write(text)
        with open(os.path.join(args.docs, name)) as f:
            if f.read() != text:
                stale.append(name)
    if stale:
        print(f"{', '.join(os.path.join(args.docs, n) for n in stale)} differ from "
              f"`{args.app} --schema`: regenerate with\n  /usr/bin/python3 tools/scene_schema.py "
              f"generate --app {args.app}" + (f"\n(fresh copies in {args.out})" if args.out else ""),
              file=sys.stderr)
        return 1
    print(f"{', '.join(documents)} match `--schema`")
    return 0


def same(apps):
    texts = [subprocess.run([a, "--schema"], check=True, capture_output=True, text=True).stdout
             for a in apps]
    if any(t != texts[0] for t in texts[1:]):
        import difflib
        diff = difflib.unified_diff(texts[0].splitlines(), texts[1].splitlines(), apps[0],
                                    apps[1], lineterm="")
        print("\n".join(list(diff)[:40]), file=sys.stderr)
        print("the programs print different schemas", file=sys.stderr)
        return 1
    if not texts[0].startswith("{"):
        print("--schema printed no JSON", file=sys.stderr)
        return 1
    print(f"{' and '.join(apps)} print the same schema ({len(texts[0])} bytes)")
    return 0


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    g = sub.add_parser("generate", help="write (or --check) docs/scene-reference.md and "
                                         "docs/scene.schema.json from APP --schema")
    g.add_argument("--app", required=True, help="fluid_app or dem_app")
    g.add_argument("--docs", default=os.path.join(here, "..", "docs"))
    g.add_argument("--check", action="store_true", help="compare instead of writing")
    g.add_argument("--out", help="with --check: write the fresh copies here")
    v = sub.add_parser("validate", help="check scenes against the JSON Schema")
    v.add_argument("schema")
    v.add_argument("scenes", nargs="+", help="scene files or folders of them")
    v.add_argument("--exclude", action="append", default=[], help="a folder to leave out")
    s = sub.add_parser("same", help="check that the programs print the same schema")
    s.add_argument("apps", nargs="+")
    args = parser.parse_args(argv)
    if args.command == "generate":
        return generate(args)
    if args.command == "same":
        return same(args.apps)
    return validate(args.schema, args.scenes, args.exclude)


if __name__ == "__main__":
    sys.exit(main())
