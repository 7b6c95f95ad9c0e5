"""Calibration overlays: figures identified from an aircraft's published performance, kept in
their own file (data/aircraft/<pack>.calibration.yaml) so that they survive regenerating the
pack from JSBSim, and merged into the pack by jsbsim2fedsim --calibration.

The overlay is a small YAML subset (block maps, numbers, plain or double-quoted strings,
comments; no lists, flow collections, anchors or block scalars), read here with the standard
library only. Format (data/aircraft/README.md, "Calibration"):

    fedsim_pack_calibration: 1
    pack: c172.yaml                 # the pack it belongs to (checked against the output name)
    procedure: "how the values were identified (tool and command line)"
    engines:
      <engine name in the pack>:
        propeller:
          power_coefficient_factor: {value: ..., source: "..."}   (written as a block map)
          thrust_coefficient_factor: ...
          factor_fade_start_advance_ratio: ...   (optional, with the next: the band over
          factor_fade_end_advance_ratio: ...      which the two factors fade out; fedsim's)

Every error names the file, the line and the field.
"""

import json
import math
import os

FORMAT_VERSION = 1

# What an overlay may set, per engine section, the accepted range of each value (the range
# fedsim's Propeller accepts: Propeller::kMinCoefficientFactor, kMaxCoefficientFactor,
# kMaxFadeAdvanceRatio) and the JSBSim element it replaces (None: fedsim's own).
CALIBRATABLE = {
    "propeller": {
        "power_coefficient_factor": (0.1, 10.0, "cp_factor"),
        "thrust_coefficient_factor": (0.1, 10.0, "ct_factor"),
        "factor_fade_start_advance_ratio": (0.0, 3.0, None),
        "factor_fade_end_advance_ratio": (0.0, 3.0, None),
    },
}

# Settings that only come in pairs (start, end), with end > start.
BANDS = (("propeller", "factor_fade_start_advance_ratio", "factor_fade_end_advance_ratio"),)


class CalibrationError(ValueError):
    pass


class Node:
    """A parsed value with the line it was read from (1-based)."""

    def __init__(self, value, line):
        self.value = value
        self.line = line


def _fail(path, line, field, problem):
    raise CalibrationError("%s:%d: %s%s" % (path, line, field + ": " if field else "", problem))


def _strip_comment(text):
    """Text before a ' #' comment (a '#' at the start of the value counts too)."""
    if text.startswith("#"):
        return ""
    at = text.find(" #")
    return text if at < 0 else text[:at]


def _scalar(text, path, line, field):
    if text.startswith('"'):
        try:
            value, end = json.JSONDecoder().raw_decode(text)
        except ValueError:
            _fail(path, line, field, "unterminated or malformed double-quoted string")
        rest = text[end:].strip()
        if rest and not rest.startswith("#"):
            _fail(path, line, field, "unexpected text after the string: %r" % rest)
        return value
    text = _strip_comment(text).strip()
    if not text:
        return None
    if text[0] in "[{|>&*!'" or text == "-":
        _fail(path, line, field, "only plain scalars, double-quoted strings and block maps are "
              "allowed in a calibration overlay (got %r)" % text)
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def parse(text, path):
    """The overlay as nested dicts of Node (a map is a Node whose value is a dict)."""
    entries = []  # (indent, key, value text, line)
    for number, raw in enumerate(text.splitlines(), start=1):
        if "\t" in raw[: len(raw) - len(raw.lstrip())]:
            _fail(path, number, "", "tabs are not allowed for indentation")
        stripped = raw.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if stripped.startswith("- "):
            _fail(path, number, "", "lists are not allowed in a calibration overlay")
        key, sep, rest = stripped.partition(":")
        if not sep or not key or key != key.strip() or (rest and not rest.startswith(" ")):
            _fail(path, number, "", "expected 'key: value' or 'key:'")
        entries.append((len(raw) - len(raw.lstrip()), key, rest.strip(), number))

    def block(start, indent, prefix):
        out = {}
        i = start
        while i < len(entries):
            ind, key, rest, line = entries[i]
            if ind < indent:
                break
            field = prefix + key
            if ind > indent:
                _fail(path, line, field, "unexpected indentation")
            if key in out:
                _fail(path, line, field, "duplicate key")
            value = _scalar(rest, path, line, field)
            if value is None:
                if i + 1 >= len(entries) or entries[i + 1][0] <= indent:
                    _fail(path, line, field, "has neither a value nor an indented block")
                child, i = block(i + 1, entries[i + 1][0], field + ".")
                out[key] = Node(child, line)
            else:
                out[key] = Node(value, line)
                i += 1
        return out, i

    if not entries:
        _fail(path, 1, "", "empty calibration overlay")
    if entries[0][0] != 0:
        _fail(path, entries[0][3], entries[0][1], "the top level must not be indented")
    tree, _ = block(0, 0, "")
    return Node(tree, 1)


def load(path):
    with open(path) as f:
        return parse(f.read(), path)


def _map(node, path, field):
    if not isinstance(node.value, dict):
        _fail(path, node.line, field, "expected a block of keys")
    return node.value


def _known(mapping, allowed, path, prefix):
    for key, node in mapping.items():
        if key not in allowed:
            _fail(path, node.line, prefix + key,
                  "unknown field (allowed: %s)" % ", ".join(sorted(allowed)))


def _required(mapping, key, path, line, prefix):
    if key not in mapping:
        _fail(path, line, prefix + key, "missing")
    return mapping[key]


def _text(node, path, field):
    if not isinstance(node.value, str) or not node.value.strip():
        _fail(path, node.line, field, "expected a non-empty text")
    return node.value


def read_overlay(path, pack_name=None):
    """The overlay's settings as a list of (engine, section, key, value, source) after checking
    every field; `pack_name` (the pack file's name) must match the overlay's `pack` entry."""
    root = load(path)
    top = _map(root, path, "")
    _known(top, {"fedsim_pack_calibration", "pack", "procedure", "engines"}, path, "")
    version = _required(top, "fedsim_pack_calibration", path, 1, "")
    if version.value != FORMAT_VERSION:
        _fail(path, version.line, "fedsim_pack_calibration",
              "unsupported format version %r (this converter reads %d)" % (version.value,
                                                                          FORMAT_VERSION))
    pack = _text(_required(top, "pack", path, 1, ""), path, "pack")
    if pack_name is not None and pack != pack_name:
        _fail(path, top["pack"].line, "pack",
              "the overlay belongs to %s, not to %s" % (pack, pack_name))
    procedure = _text(_required(top, "procedure", path, 1, ""), path, "procedure")
    engines = _map(_required(top, "engines", path, 1, ""), path, "engines")
    settings = []
    for engine, engine_node in engines.items():
        prefix = "engines.%s." % engine
        sections = _map(engine_node, path, "engines." + engine)
        _known(sections, set(CALIBRATABLE), path, prefix)
        for section, section_node in sections.items():
            keys = _map(section_node, path, prefix + section)
            _known(keys, set(CALIBRATABLE[section]), path, prefix + section + ".")
            for key, entry in keys.items():
                field = "%s%s.%s" % (prefix, section, key)
                item = _map(entry, path, field)
                _known(item, {"value", "source"}, path, field + ".")
                value = _required(item, "value", path, entry.line, field + ".")
                low, high, _ = CALIBRATABLE[section][key]
                if (isinstance(value.value, bool) or not isinstance(value.value, (int, float))
                        or not math.isfinite(value.value)):
                    _fail(path, value.line, field + ".value",
                          "expected a finite number, got %r" % (value.value,))
                if not low <= value.value <= high:
                    _fail(path, value.line, field + ".value",
                          "value %g is outside the allowed range [%g, %g]" % (value.value, low,
                                                                              high))
                source = _text(_required(item, "source", path, entry.line, field + "."), path,
                               field + ".source")
                settings.append({"engine": engine, "section": section, "key": key,
                                 "value": float(value.value), "source": source,
                                 "line": value.line})
            for band_section, start_key, end_key in BANDS:
                if band_section != section:
                    continue
                start = keys.get(start_key)
                end = keys.get(end_key)
                section_field = prefix + section + "."
                if (start is None) != (end is None):
                    present, missing = (start_key, end_key) if end is None else (end_key, start_key)
                    _fail(path, keys[present].line, section_field + present,
                          "needs %s too (a band has two ends)" % missing)
                if start is not None:
                    start_value = next(s["value"] for s in settings
                                       if s["engine"] == engine and s["key"] == start_key)
                    end_setting = next(s for s in settings
                                       if s["engine"] == engine and s["key"] == end_key)
                    if not end_setting["value"] > start_value:
                        _fail(path, end_setting["line"], section_field + end_key + ".value",
                              "must exceed %s (%g)" % (start_key, start_value))
    return {"procedure": procedure, "settings": settings, "path": path}


def insert_after(mapping, after_keys, key, value):
    """A copy of `mapping` with key: value placed after the last of `after_keys` present (or
    replaced in place if the key is already there)."""
    if key in mapping:
        out = dict(mapping)
        out[key] = value
        return out
    anchor = None
    for k in mapping:
        if k in after_keys:
            anchor = k
    out = {}
    if anchor is None:
        out[key] = value
    for k, v in mapping.items():
        out[k] = v
        if k == anchor:
            out[key] = value
    return out


def apply(overlay, sections, notes, commented):
    """Merges the overlay's settings into the converted pack sections (in place); each value
    gets a comment naming the overlay, and a note with its source goes into `notes`.
    `commented(value, comment)` wraps a value with its comment."""
    path = overlay["path"]
    name = os.path.basename(path)
    engines = {e["name"]: e for e in sections["propulsion"]["engines"]}
    for s in overlay["settings"]:
        field = "engines.%s.%s.%s" % (s["engine"], s["section"], s["key"])
        if s["engine"] not in engines:
            _fail(path, s["line"], field, "the pack has no engine named '%s' (it has: %s)" %
                  (s["engine"], ", ".join(engines) or "none"))
        engine = engines[s["engine"]]
        if s["section"] not in engine:
            _fail(path, s["line"], field, "engine '%s' has no %s section" %
                  (s["engine"], s["section"]))
        section = engine[s["section"]]
        replaced = section.get(s["key"])
        note = "engine '%s' %s %s = %g calibrated (%s): %s" % (
            s["engine"], s["section"], s["key"], s["value"], name, s["source"])
        if replaced is not None:
            old = replaced.value if hasattr(replaced, "value") else replaced
            jsbsim_name = CALIBRATABLE[s["section"]][s["key"]][2]
            note += (" (replaces JSBSim's <%s> %g)" % (jsbsim_name, old) if jsbsim_name
                     else " (replaces %g)" % old)
        engine[s["section"]] = insert_after(
            section, ("thrust_coefficient", "power_coefficient", "thrust_coefficient_factor",
                      "power_coefficient_factor", "factor_fade_start_advance_ratio",
                      "factor_fade_end_advance_ratio"),
            s["key"], commented(s["value"], "calibrated: " + name))
        notes.append(note)
    notes.append("calibration procedure (%s): %s" % (name, overlay["procedure"]))
