"""Reading JSBSim XML: units, locations, tables and numeric evaluation of <function> trees."""

import math
import re
import xml.etree.ElementTree as ET

# --- units -------------------------------------------------------------------------------
# SI value of one JSBSim unit. JSBSim states units per element; an element without a unit
# attribute is in the unit the reading code asks for (the `default` argument below).
FT = 0.3048
IN = 0.0254
LB_MASS = 0.45359237                 # kg per pound (mass)
LBF = LB_MASS * 9.80665              # N per pound-force
SLUG = LBF / FT                      # kg per slug
UNITS = {
    "FT": FT, "IN": IN, "M": 1.0, "CM": 0.01, "KM": 1000.0,
    "FT2": FT * FT, "M2": 1.0, "IN2": IN * IN, "CM2": 1e-4,
    "FT3": FT ** 3, "IN3": IN ** 3, "M3": 1.0, "CC": 1e-6, "L": 1e-3,
    "LBS": LB_MASS, "KG": 1.0, "SLUG": SLUG,  # weights read as masses; thrust uses LBF
    "SLUG*FT2": SLUG * FT * FT, "KG*M2": 1.0,
    "DEG": math.pi / 180.0, "RAD": 1.0,
    "LBS/FT": LBF / FT, "N/M": 1.0,
    "LBS/FT/SEC": LBF / FT, "N/M/SEC": 1.0, "LBS/FT/S": LBF / FT,
    "INHG": 70.7180803 * LBF / (FT * FT), "PSF": LBF / (FT * FT), "PSI": LBF / (IN * IN), "PA": 1.0,
    "ATM": 101325.0, "HP": 745.6998715822702, "WATTS": 1.0, "KW": 1000.0,
    "N": 1.0,
}
PSF = UNITS["PSF"]


def to_si(value, unit):
    if unit not in UNITS:
        raise ValueError("unknown JSBSim unit '%s'" % unit)
    return value * UNITS[unit]


def number_text(element):
    return float(element.text.strip())


def value_si(parent, tag, default_unit, fallback=None):
    """The SI value of child `tag` (unit attribute, else `default_unit`); fallback if absent."""
    element = parent.find(tag)
    if element is None:
        if fallback is None:
            raise ValueError("<%s> has no <%s>" % (parent.tag, tag))
        return fallback
    return to_si(number_text(element), element.get("unit", default_unit))


def plain_number(parent, tag, fallback=None):
    element = parent.find(tag)
    if element is None:
        if fallback is None:
            raise ValueError("<%s> has no <%s>" % (parent.tag, tag))
        return fallback
    return number_text(element)


def structural_to_pack(location, default_unit="IN"):
    """A JSBSim structural-frame location (x aft, y right, z up) as pack-frame metres
    (x forward, y right, z down) about the same origin."""
    unit = location.get("unit", default_unit)
    x, y, z = (to_si(number_text(location.find(axis)), unit) for axis in "xyz")
    return [-x, y, -z]


def named_location(parent, name):
    for loc in parent.findall("location"):
        if loc.get("name") == name:
            return loc
    return None


# --- tables --------------------------------------------------------------------------------
class JsbTable:
    """A JSBSim <table>: independent variables in lookup order (row, column, table) and data.

    rows/cols/pages hold breakpoints; values is nested like the fedsim pack writes them:
    1-D [v], 2-D [[v per column] per row], 3-D [[[...]] per page]."""

    def __init__(self, element):
        self.variables = {}
        for iv in element.findall("independentVar"):
            self.variables[iv.get("lookup", "row")] = iv.text.strip()
        datas = element.findall("tableData")
        if len(datas) > 1 or "table" in self.variables:
            self.dimensions = 3
            self.pages = [float(d.get("breakPoint")) for d in datas]
            parsed = [self._parse_2d(d.text) for d in datas]
            self.rows, self.cols = parsed[0][0], parsed[0][1]
            for p in parsed:
                if p[0] != self.rows or p[1] != self.cols:
                    raise ValueError("3-D table pages have different breakpoints")
            self.values = [p[2] for p in parsed]
        else:
            lines = [l.split() for l in datas[0].text.strip().splitlines() if l.split()]
            if "column" in self.variables:
                self.dimensions = 2
                self.rows, self.cols, self.values = self._parse_2d(datas[0].text)
            else:
                self.dimensions = 1
                self.rows = [float(l[0]) for l in lines]
                self.values = [float(l[1]) for l in lines]

    @staticmethod
    def _parse_2d(text):
        lines = [l.split() for l in text.strip().splitlines() if l.split()]
        cols = [float(v) for v in lines[0]]
        rows = [float(l[0]) for l in lines[1:]]
        values = [[float(v) for v in l[1:]] for l in lines[1:]]
        for row in values:
            if len(row) != len(cols):
                raise ValueError("table row with %d values for %d columns" % (len(row), len(cols)))
        return rows, cols, values

    def lookup_order(self):
        """Independent variable names in fedsim order: 1-D (row), 2-D (row, column),
        3-D (page = JSBSim 'table', row, column)."""
        if self.dimensions == 1:
            return [self.variables["row"]]
        if self.dimensions == 2:
            return [self.variables["row"], self.variables["column"]]
        return [self.variables["table"], self.variables["row"], self.variables["column"]]

    def axes(self):
        if self.dimensions == 1:
            return [self.rows]
        if self.dimensions == 2:
            return [self.rows, self.cols]
        return [self.pages, self.rows, self.cols]

    def __call__(self, env):
        keys = [env.get(name, 0.0) for name in self.lookup_order()]
        return interpolate(self.axes(), self.values, keys)


def interpolate(axes, values, keys):
    """Clamped multilinear interpolation over nested lists (same rule as fedsim's tables)."""
    if not axes:
        return values
    axis, key = axes[0], keys[0]
    if len(axis) == 1 or key <= axis[0]:
        return interpolate(axes[1:], values[0], keys[1:])
    if key >= axis[-1]:
        return interpolate(axes[1:], values[-1], keys[1:])
    i = max(j for j in range(len(axis) - 1) if axis[j] <= key)
    f = (key - axis[i]) / (axis[i + 1] - axis[i])
    low = interpolate(axes[1:], values[i], keys[1:])
    high = interpolate(axes[1:], values[i + 1], keys[1:])
    return low * (1.0 - f) + high * f


# --- functions -----------------------------------------------------------------------------
PROPERTY_TAGS = ("property", "p")
VALUE_TAGS = ("value", "v")
TABLE_TAGS = ("table", "t")


def function_body(function):
    """The single operation element of a <function> (skipping <description>)."""
    body = [c for c in function if c.tag != "description"]
    if len(body) != 1:
        raise ValueError("function '%s' has %d top-level operations" %
                         (function.get("name"), len(body)))
    return body[0]


def evaluate(element, env):
    """Numeric value of a JSBSim function element; unknown properties read as 0."""
    tag = element.tag
    kids = [c for c in element if c.tag != "description"]
    if tag in PROPERTY_TAGS:
        name = element.text.strip()
        sign = -1.0 if name.startswith("-") else 1.0
        return sign * env.get(name.lstrip("-"), 0.0)
    if tag in VALUE_TAGS:
        return float(element.text)
    if tag in TABLE_TAGS:
        return JsbTable(element)(env)
    if tag == "function":
        return evaluate(function_body(element), env)
    values = [evaluate(k, env) for k in kids]
    simple = {
        "product": lambda v: math.prod(v),
        "sum": lambda v: sum(v),
        "difference": lambda v: v[0] - sum(v[1:]),
        "quotient": lambda v: v[0] / v[1] if v[1] != 0 else float("inf"),
        "abs": lambda v: abs(v[0]),
        "atan2": lambda v: math.atan2(v[0], v[1]),
        "max": lambda v: max(v), "min": lambda v: min(v),
        "ge": lambda v: float(v[0] >= v[1]), "gt": lambda v: float(v[0] > v[1]),
        "le": lambda v: float(v[0] <= v[1]), "lt": lambda v: float(v[0] < v[1]),
        "eq": lambda v: float(v[0] == v[1]), "nq": lambda v: float(v[0] != v[1]),
        "pow": lambda v: v[0] ** v[1], "sqrt": lambda v: math.sqrt(v[0]),
    }
    if tag in simple:
        return simple[tag](values)
    if tag == "ifthen":
        return values[1] if values[0] != 0.0 else values[2]
    raise ValueError("JSBSim function operation <%s> is not supported" % tag)


def parse(path):
    return ET.parse(path).getroot()


def property_name(component_name):
    """JSBSim's property for an FCS component named without a path: fcs/<lower-dashed>."""
    if "/" in component_name:
        return component_name
    return "fcs/" + re.sub(r"\s+", "-", component_name.strip().lower())
