"""Translation of JSBSim <aerodynamics> functions into fedsim coefficient terms.

A JSBSim coefficient function is (almost always) a product of properties, constants and at
most one table, with the dimensional factors qbar * S (and b or c for moments) inside it. A
fedsim term is a constant or a table times named variables, and the model applies qbar S (b, c)
itself. So each factor of the product is classified: a dimensional factor is checked off, a
constant folds into the term's gain, b/(2V) or c/(2V) pairs with a rate into p_hat & co, a
property maps to a fedsim variable (with a unit factor for degrees), a named aerodynamic
function becomes a pack factor, and the table becomes the term's lookup (its breakpoints
converted to the fedsim variable's unit). Anything else is reported and the term is left out.
"""

import math
import re

import jsbsim_xml as jx

R2D = 180.0 / math.pi

# JSBSim property -> (fedsim variable, k) with property value = k * fedsim value.
VARIABLES = {
    "aero/alpha-rad": ("alpha_rad", 1.0), "aero/alpha-deg": ("alpha_rad", R2D),
    "aero/mag-alpha-rad": ("abs_alpha_rad", 1.0), "aero/mag-alpha-deg": ("abs_alpha_rad", R2D),
    "aero/beta-rad": ("beta_rad", 1.0), "aero/beta-deg": ("beta_rad", R2D),
    "aero/mag-beta-rad": ("abs_beta_rad", 1.0), "aero/mag-beta-deg": ("abs_beta_rad", R2D),
    "velocities/mach": ("mach", 1.0),
    "fcs/elevator-pos-rad": ("elevator_rad", 1.0), "fcs/elevator-pos-deg": ("elevator_rad", R2D),
    "fcs/mag-elevator-pos-rad": ("abs_elevator_rad", 1.0),
    "fcs/rudder-pos-rad": ("rudder_rad", 1.0), "fcs/rudder-pos-deg": ("rudder_rad", R2D),
    "fcs/mag-rudder-pos-rad": ("abs_rudder_rad", 1.0),
    "fcs/mag-aileron-pos-rad": ("abs_aileron_rad", 1.0),
    "fcs/flap-pos-deg": ("flap_deg", 1.0), "fcs/flap-pos-rad": ("flap_deg", 1.0 / R2D),
    "fcs/flap-pos-norm": ("flap_norm", 1.0),
    "gear/gear-pos-norm": ("gear_norm", 1.0),
    "fcs/speedbrake-pos-norm": ("speedbrake_norm", 1.0),
    "fcs/spoiler-pos-norm": ("spoiler_norm", 1.0),
    "aero/h_b-mac-ft": ("h_over_b", 1.0),
    "aero/stall-hyst-norm": ("stall_hysteresis", 1.0),
    "aero/cl-squared": ("cl_squared", 1.0),
}
# Only as a table input (as a multiplier qbar is a dimensional factor).
TABLE_ONLY = {"aero/qbar-psf": ("qbar_pa", 1.0 / jx.PSF)}

DIMENSIONS = {"aero/qbar-area": ("q", "S"), "aero/qbar-psf": ("q",), "metrics/Sw-sqft": ("S",),
              "metrics/bw-ft": ("b",), "metrics/cbarw-ft": ("c",)}
HALF_INVERSE_SPEED = {"aero/bi2vel": "b", "aero/ci2vel": "c"}
RATES = {"velocities/p-aero-rad_sec": ("p_hat", "b"), "velocities/r-aero-rad_sec": ("r_hat", "b"),
         "velocities/q-aero-rad_sec": ("q_hat", "c"), "aero/alphadot-rad_sec": ("alphadot_hat", "c"),
         "aero/betadot-rad_sec": ("betadot_hat", "b")}
AXES = {"LIFT": ("lift", ("q", "S")), "DRAG": ("drag", ("q", "S")),
        "SIDE": ("side_force", ("q", "S")), "ROLL": ("roll_moment", ("q", "S", "b")),
        "PITCH": ("pitch_moment", ("q", "S", "c")), "YAW": ("yaw_moment", ("q", "S", "b"))}


class Untranslatable(Exception):
    pass


def short_name(function_name):
    return re.sub(r"[^A-Za-z0-9_]", "_", function_name.split("/")[-1])


class AeroTranslator:
    def __init__(self, aerodynamics, extra_variables, notes):
        """extra_variables: further property -> (variable, k), e.g. the aileron property the
        FCS analysis found."""
        self.aero = aerodynamics
        self.variables = dict(VARIABLES)
        self.variables.update(extra_variables)
        self.notes = notes
        self.functions = {f.get("name"): f for f in aerodynamics.findall("function")}
        self.factors = {}        # JSBSim function name -> fedsim factor term
        self.factor_order = []

    # -- tables ------------------------------------------------------------------------
    def _table(self, element, gain):
        table = jx.JsbTable(element)
        names = table.lookup_order()
        out, axes = {}, table.axes()
        keys = ["row"] if table.dimensions == 1 else (["row", "column"] if table.dimensions == 2
                                                       else ["page", "row", "column"])
        for key, prop, bps in zip(keys, names, axes):
            variable, k = self._table_input(prop)
            out[key] = variable
            out[key + "_breakpoints"] = [bp / k for bp in bps]
        out["values"] = _scaled(table.values, gain)
        return _ordered_table(out, table.dimensions)

    def _table_input(self, prop):
        if prop in self.variables:
            return self.variables[prop]
        if prop in TABLE_ONLY:
            return TABLE_ONLY[prop]
        raise Untranslatable("table input '%s' has no fedsim variable" % prop)

    # -- products ------------------------------------------------------------------------
    def translate(self, function, required_dims):
        """A fedsim term dict for one JSBSim function; raises Untranslatable."""
        body = jx.function_body(function)
        factors = list(body) if body.tag == "product" else [body]
        gain, dims, halves, rates, multipliers, tables = 1.0, [], [], [], [], []
        for f in factors:
            if f.tag in jx.VALUE_TAGS:
                gain *= float(f.text)
            elif f.tag in jx.TABLE_TAGS:
                tables.append(f)
            elif f.tag in jx.PROPERTY_TAGS:
                prop = f.text.strip()
                if prop.startswith("-"):
                    gain, prop = -gain, prop[1:]
                if prop in DIMENSIONS and required_dims is not None:
                    dims.extend(DIMENSIONS[prop])
                elif prop in HALF_INVERSE_SPEED:
                    halves.append(HALF_INVERSE_SPEED[prop])
                elif prop in RATES:
                    rates.append(RATES[prop])
                elif prop in self.variables:
                    variable, k = self.variables[prop]
                    gain *= k
                    multipliers.append(variable)
                    if variable == "cl_squared":
                        self.notes.append("aero/cl-squared: fedsim squares this evaluation's CL; "
                                          "JSBSim uses the previous frame's")
                elif prop in self.functions and required_dims is not None:
                    multipliers.append(self._factor(prop))
                else:
                    raise Untranslatable("property '%s' has no fedsim variable" % prop)
            else:
                raise Untranslatable("operation <%s> inside the product" % f.tag)
        if required_dims is not None and sorted(dims) != sorted(required_dims):
            raise Untranslatable("dimensional factors %s, expected %s" %
                                 ("*".join(dims) or "none", "*".join(required_dims)))
        multipliers.extend(self._pair_rates(halves, rates))
        if len(tables) > 1:
            raise Untranslatable("more than one table in the product")
        term = {"name": short_name(function.get("name"))}
        description = function.find("description")
        if description is not None and description.text and description.text.strip():
            term["description"] = " ".join(description.text.split())
        if tables:
            term["table"] = self._table(tables[0], gain)
        else:
            term["value"] = gain
        if multipliers:
            term["multiply_by"] = multipliers
        return term

    @staticmethod
    def _pair_rates(halves, rates):
        """b/(2V) pairs with p, r, betadot; c/(2V) with q, alphadot."""
        out, halves = [], list(halves)
        for variable, length in rates:
            if length not in halves:
                raise Untranslatable("rate for %s without its %s/(2V) factor" % (variable, length))
            halves.remove(length)
            out.append(variable)
        if halves:
            raise Untranslatable("%s/(2V) without a rate" % halves[0])
        return out

    def _factor(self, function_name):
        if function_name not in self.factors:
            term = self.translate(self.functions[function_name], None)
            term["name"] = short_name(function_name)
            self.factors[function_name] = term
            self.factor_order.append(function_name)
        return self.factors[function_name]["name"]

    # -- whole section -------------------------------------------------------------------
    def axes(self):
        out = {name: [] for name, _ in AXES.values()}
        for axis in self.aero.findall("axis"):
            jsb_name = axis.get("name")
            if jsb_name not in AXES:
                self.notes.append("aerodynamic axis '%s' is not translated (fedsim uses LIFT, "
                                  "DRAG, SIDE, ROLL, PITCH, YAW)" % jsb_name)
                continue
            fedsim_axis, dims = AXES[jsb_name]
            for function in axis.findall("function"):
                try:
                    out[fedsim_axis].append(self.translate(function, dims))
                except Untranslatable as why:
                    self.notes.append("%s term %s left out: %s" %
                                      (fedsim_axis, function.get("name"), why))
        for name in self.functions:
            if name not in self.factors:
                self.notes.append("aerodynamic function %s is not used by any coefficient and "
                                  "is left out" % name)
        return out

    def factor_terms(self):
        return [self.factors[n] for n in self.factor_order]


def _scaled(values, gain):
    if isinstance(values, list):
        return [_scaled(v, gain) for v in values]
    return values * gain


def _ordered_table(t, dimensions):
    keys = (["row", "row_breakpoints"] if dimensions == 1 else
            ["row", "column", "row_breakpoints", "column_breakpoints"] if dimensions == 2 else
            ["page", "row", "column", "page_breakpoints", "row_breakpoints", "column_breakpoints"])
    out = {k: t[k] for k in keys}
    out["values"] = t["values"]
    return out


# --- evaluation of translated terms (for the converter's own sign checks) --------------------
def evaluate_term(term, env):
    if "table" in term:
        t = term["table"]
        keys = [k for k in ("page", "row", "column") if k in t]
        value = jx.interpolate([t[k + "_breakpoints"] for k in keys], t["values"],
                               [env.get(t[k], 0.0) for k in keys])
    else:
        value = term["value"]
    for name in term.get("multiply_by", []):
        value *= env.get(name, 0.0)
    return value


def evaluate_axis(terms, factors, env):
    env = dict(env)
    for f in factors:
        env[f["name"]] = evaluate_term(f, env)
    return sum(evaluate_term(t, env) for t in terms)
