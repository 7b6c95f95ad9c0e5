"""A small YAML writer for fedsim aircraft packs: block maps, flow lists of numbers (one table
row per line) and trailing comments, so that generated packs read like hand-written ones."""

import json
import re


class Commented:
    """A scalar or flow list followed by `# comment` on its line."""

    def __init__(self, value, comment):
        self.value = value
        self.comment = comment


def number(x):
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, int):
        return str(x)
    if x == 0.0:
        return "0.0"
    text = "%.10g" % x
    if "e" not in text and "." not in text:
        text += ".0"
    return text


_PLAIN = re.compile(r"^[A-Za-z][A-Za-z0-9_ ,.()/+*=<>-]*$")
_RESERVED = {"true", "false", "yes", "no", "on", "off", "null", "y", "n"}


def string(s):
    if _PLAIN.match(s) and s.lower() not in _RESERVED and ": " not in s and not s.endswith(" "):
        return s
    return json.dumps(s)


def scalar(v):
    if isinstance(v, str):
        return string(v)
    return number(v)


def _is_scalar(v):
    return isinstance(v, (int, float, str, bool))


def _is_flow_list(v):
    """Numbers go on one line (a table row); names only while the line stays short."""
    if not isinstance(v, list) or not all(_is_scalar(x) for x in v):
        return False
    return all(not isinstance(x, str) for x in v) or len(flow(v)) <= 72


def flow(v):
    return "[" + ", ".join(scalar(x) for x in v) + "]"


def _inline(v):
    """Text of a value that fits after 'key: ' on one line, or None."""
    comment = ""
    if isinstance(v, Commented):
        v, comment = v.value, "  # " + v.comment
    if _is_scalar(v):
        return scalar(v) + comment
    if _is_flow_list(v):
        return flow(v) + comment
    if isinstance(v, dict) and not v:
        return "{}" + comment
    return None


def emit(value, indent=0):
    """Lines of a block map (dict) or a block sequence (list) at `indent` spaces."""
    pad = " " * indent
    lines = []
    if isinstance(value, dict):
        for key, v in value.items():
            text = _inline(v)
            if text is not None:
                lines.append("%s%s: %s" % (pad, key, text))
            else:
                lines.append("%s%s:" % (pad, key))
                lines.extend(emit(v, indent + 2))
        return lines
    for item in value:
        text = _inline(item)
        if text is not None:
            lines.append("%s- %s" % (pad, text))
            continue
        sub = emit(item, indent + 2)
        lines.append("%s- %s" % (pad, sub[0].lstrip()))
        lines.extend(sub[1:])
    return lines


def document(header_comments, sections):
    """A whole pack: comment lines, then each top-level section separated by a blank line."""
    out = ["# " + c if c else "#" for c in header_comments]
    for key, v in sections.items():
        out.append("")
        text = _inline(v)
        out.extend(["%s: %s" % (key, text)] if text is not None else [key + ":"] + emit(v, 2))
    return "\n".join(out) + "\n"
