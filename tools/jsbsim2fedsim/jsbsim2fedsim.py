#!/usr/bin/env python3
"""jsbsim2fedsim: write a fedsim aircraft pack (YAML, SI) from a JSBSim aircraft definition.

Usage:
  jsbsim2fedsim.py AIRCRAFT.xml --output PACK.yaml [--engine-dir DIR] [--jsbsim-root DIR]
                   [--commit SHA] [--name NAME] [--calibration OVERLAY.yaml]

Reads the aircraft file, the engine, propeller and thruster files it names (from
--engine-dir, by default <jsbsim-root>/engine) and its autopilot file (next to it; only a wing
leveller is translated, see jsbsim_autopilot.py), converts every figure to SI in fedsim's pack
frame (body axes x forward, y right, z down, metres from the JSBSim structural origin; JSBSim's
structural frame is x aft, y right, z up, usually inches) and translates the aerodynamic
functions into fedsim coefficient terms. Whatever it cannot translate is listed on stderr and in
the pack's metadata.notes. --calibration merges a calibration overlay (figures identified
from the aircraft's published performance, e.g. data/aircraft/c172.calibration.yaml; see
calibration.py), so that they survive regenerating the pack. Python 3 standard library only.
The pack format is documented in data/aircraft/README.md.
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import calibration  # noqa: E402
import jsbsim_aero  # noqa: E402
import jsbsim_autopilot  # noqa: E402
import jsbsim_fcs  # noqa: E402
import jsbsim_xml as jx  # noqa: E402
from pack_yaml import Commented, document  # noqa: E402

R2D = 180.0 / math.pi


def commented(value, element, default_unit):
    """An SI value with the JSBSim figure it came from as a comment."""
    unit = element.get("unit", default_unit)
    return Commented(value, "%s %s" % (element.text.strip(), unit))


def xyz_text(location, default_unit="IN"):
    vals = [location.find(a).text.strip() for a in "xyz"]
    return "JSBSim (%s) %s" % (", ".join(vals), location.get("unit", default_unit))


class Converter:
    def __init__(self, aircraft_path, engine_dir, notes, pitch_trim=None):
        self.pitch_trim = pitch_trim  # (kind, rate_per_s) or None: no trim system in the pack
        self.root = jx.parse(aircraft_path)
        self.engine_dir = engine_dir
        self.notes = notes
        self.files_read = [aircraft_path]
        fc = self.root.find("flight_control")
        self.fcs = jsbsim_fcs.StaticFcs(fc, notes) if fc is not None else None
        self.aero_element = self.root.find("aerodynamics")
        self.aero_properties = {e.text.strip().lstrip("-") for e in self.aero_element.iter()
                                if e.tag in jx.PROPERTY_TAGS or e.tag == "independentVar"}
        self.surfaces = {}
        self.autopilots = []  # (label, file read or None, <autopilot> root or None, placeholder note)
        self.wing_leveller = None
        self._note_skipped_sections()

    def _note_skipped_sections(self):
        for system in self.root.findall("system"):
            self.notes.append("JSBSim <system> '%s' is not translated (systems belong to "
                              "fedsim's own models)" % (system.get("name") or system.get("file")))
        for ap in self.root.findall("autopilot"):
            # Replaced once flight_controls() has looked for a wing leveller in it.
            label = ap.get("name") or ap.get("file")
            path, root = self._autopilot_root(ap)
            placeholder = "JSBSim <autopilot> '%s' is not translated" % label
            if root is None:
                placeholder += " (its file %s is not next to the aircraft file)" % ap.get("file")
            self.notes.append(placeholder)
            self.autopilots.append((label, path, root, placeholder))

    def _autopilot_root(self, ap):
        """(path, root) of an <autopilot>: inline, or its file="..." next to the aircraft file
        (JSBSim looks there, then in its Systems folder); (None, None) if not found."""
        name = ap.get("file")
        if not name:
            return None, ap
        if not name.endswith(".xml"):
            name += ".xml"
        folder = os.path.dirname(self.files_read[0])
        for path in (os.path.join(folder, name), os.path.join(folder, "Systems", name)):
            if os.path.exists(path):
                self.files_read.append(path)
                return path, jx.parse(path)
        return None, None

    # -- metadata and geometry ------------------------------------------------------------
    def geometry(self):
        m = self.root.find("metrics")
        out = {}
        for key, tag, unit in (("wing_area_m2", "wingarea", "FT2"), ("wing_span_m", "wingspan", "FT"),
                               ("mean_chord_m", "chord", "FT")):
            out[key] = commented(jx.value_si(m, tag, unit), m.find(tag), unit)
        for key, name in (("aero_reference_point_m", "AERORP"), ("pilot_eye_point_m", "EYEPOINT"),
                          ("visual_reference_point_m", "VRP")):
            loc = jx.named_location(m, name)
            if loc is not None:
                out[key] = Commented(jx.structural_to_pack(loc), xyz_text(loc))
            elif key != "visual_reference_point_m":
                raise ValueError("metrics has no %s location" % name)
        unused = [t for t in ("htailarea", "htailarm", "vtailarea", "vtailarm") if m.find(t) is not None]
        if unused:
            self.notes.append("metrics %s are not used (fedsim's aerodynamics are coefficient "
                              "terms)" % ", ".join(unused))
        return out

    # -- mass -------------------------------------------------------------------------------
    def mass(self):
        mb = self.root.find("mass_balance")
        out = {"empty_mass_kg": commented(jx.value_si(mb, "emptywt", "LBS"), mb.find("emptywt"), "LBS")}
        cg = jx.named_location(mb, "CG")
        out["empty_cg_m"] = Commented(jx.structural_to_pack(cg), xyz_text(cg))
        out["empty_inertia"] = self._inertia(mb)
        masses = []
        for pm in mb.findall("pointmass"):
            if pm.find("form") is not None:
                self.notes.append("point mass '%s': its own <form> inertia is left out" % pm.get("name"))
            masses.append({"name": pm.get("name").strip().lower(),
                           "mass_kg": commented(jx.value_si(pm, "weight", "LBS"), pm.find("weight"), "LBS"),
                           "position_m": Commented(jx.structural_to_pack(pm.find("location")),
                                                   xyz_text(pm.find("location")))})
        if masses:
            out["point_masses"] = masses
        tanks = self._tanks()
        if tanks:
            out["fuel_tanks"] = tanks
        return out

    def _inertia(self, mb):
        """Products of inertia as integrals in body axes. JSBSim's XML gives the tensor's
        off-diagonal elements in the structural frame (negated_crossproduct_inertia="true", the
        default) or the products themselves ("false"); turning x and z round flips the xy and
        yz elements and keeps xz."""
        raw = {k: jx.value_si(mb, k, "SLUG*FT2", 0.0) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
        elements_given = mb.get("negated_crossproduct_inertia", "true") == "true"
        sign = -1.0 if elements_given else 1.0  # structural product = sign * XML value
        products = {"ixy": -sign * raw["ixy"], "ixz": sign * raw["ixz"], "iyz": -sign * raw["iyz"]}
        out = {}
        for k in ("ixx", "iyy", "izz"):
            out[k + "_kgm2"] = commented(raw[k], mb.find(k), "SLUG*FT2")
        for k, v in products.items():
            element = mb.find(k)
            out[k + "_kgm2"] = commented(v, element, "SLUG*FT2") if element is not None else 0.0
        return out

    def _tanks(self):
        prop = self.root.find("propulsion")
        uses_jet = bool(prop.findall("engine")) and any(
            self._engine_root(e).tag == "turbine_engine" for e in prop.findall("engine"))
        out = []
        for i, tank in enumerate(prop.findall("tank")):
            loc = tank.find("location")
            pos = jx.structural_to_pack(loc)
            side = "left" if pos[1] < 0 else ("right" if pos[1] > 0 else "centre")
            fuel_name = (tank.findtext("type") or ("JET-A" if uses_jet else "AVGAS")).strip().upper()
            entry = {"name": "tank %d %s" % (i, side),
                     "position_m": Commented(pos, xyz_text(loc)),
                     "capacity_kg": commented(jx.value_si(tank, "capacity", "LBS"), tank.find("capacity"), "LBS"),
                     "initial_kg": commented(jx.value_si(tank, "contents", "LBS"), tank.find("contents"), "LBS")}
            if tank.find("radius") is not None:
                self.notes.append("tank %d: radius kept; JSBSim adds 0.4 m r^2 of tank inertia, "
                                  "which fedsim's mass balance does not (yet) carry" % i)
                entry["radius_m"] = commented(jx.value_si(tank, "radius", "IN"), tank.find("radius"), "IN")
            entry["fuel"] = "jet_a" if fuel_name.startswith("JET") else "avgas"
            for extra in ("standpipe", "unusable", "priority", "temperature", "drain_location"):
                if tank.find(extra) is not None:
                    self.notes.append("tank %d: <%s> is not translated" % (i, extra))
            out.append(entry)
        return out

    # -- flight controls --------------------------------------------------------------------
    def flight_controls(self):
        out = {}
        # fedsim and JSBSim agree on elevator (+ = stick forward, nose down) and aileron
        # (+ = stick right, right wing down) commands; JSBSim's rudder command is positive
        # for left pedal (FlightGear negates its rudder input), so fedsim's +1 is JSBSim's -1.
        # JSBSim derives fcs/<surface>-pos-deg and fcs/mag-<surface>-pos-rad from the
        # -pos-rad property the FCS writes, so the travel is read off the latter.
        aileron = self._aileron_candidates()
        for surface, written, used_names, command, sign in (
                ("elevator", "fcs/elevator-pos-rad",
                 ["fcs/elevator-pos-rad", "fcs/elevator-pos-deg", "fcs/mag-elevator-pos-rad"],
                 "fcs/elevator-cmd-norm", 1.0),
                ("aileron", aileron[0] if aileron else None, aileron, "fcs/aileron-cmd-norm", 1.0),
                ("rudder", "fcs/rudder-pos-rad",
                 ["fcs/rudder-pos-rad", "fcs/rudder-pos-deg", "fcs/mag-rudder-pos-rad"],
                 "fcs/rudder-cmd-norm", -1.0)):
            if not any(p in self.aero_properties for p in used_names):
                continue
            if self.fcs is None or written not in self.fcs.producer:
                self.notes.append("the aerodynamics use the %s but no FCS component writes %s: "
                                  "no %s in the pack" % (surface, written, surface))
                continue
            prop = written
            k = self._unit_factor(prop)
            damper = self.fcs.yaw_damper(prop, command, sign, self.notes) if surface == "rudder" else None
            translated = (jsbsim_fcs.YAW_RATE,) if damper else ()
            if surface == "aileron":
                self.wing_leveller = self._find_wing_leveller(prop)
            leveller_input = (self.wing_leveller.fcs_input,) if surface == "aileron" and \
                self.wing_leveller else ()
            s = self.fcs.surface(prop, command, sign, self.notes, translated, leveller_input)
            self.surfaces[surface] = (prop, s, k)
            out[surface] = self._surface_entry(s, k)
            if damper:
                out["yaw_damper"] = self._yaw_damper_entry(damper)
        if self.pitch_trim and "elevator" in out:
            kind, rate = self.pitch_trim
            out["pitch_trim"] = {"kind": kind, "rate_per_s": Commented(
                rate, "fedsim's figure (--pitch-trim): JSBSim files give no trim rate")}
        if "aileron" not in out:
            self._place_autopilot_notes(None, {})
        if self.wing_leveller:
            out["wing_leveller"] = self._wing_leveller_entry(self.wing_leveller)
        for surface, prop_candidates in (("flaps", ["fcs/flap-pos-deg", "fcs/flap-pos-rad", "fcs/flap-pos-norm"]),
                                         ("speedbrake", ["fcs/speedbrake-pos-norm"]),
                                         ("spoilers", ["fcs/spoiler-pos-norm"])):
            used = [p for p in prop_candidates if p in self.aero_properties]
            if used:
                entry = self._kinematic_entry(used[0], surface == "flaps")
                if entry:
                    out[surface] = entry
        return out

    def _yaw_damper_entry(self, damper):
        """fedsim's yaw_damper section: JSBSim's chain of gains on the air-relative yaw rate,
        sampled at its Mach breakpoints (no washout: JSBSim's chain has none; a filter on the
        path is not translated)."""
        self.notes.append("yaw damper (%s on %s) translated as flight_controls.yaw_damper, its "
                          "gain sampled at the Mach breakpoints of its schedules" %
                          (", ".join("'%s'" % n for n in damper["components"]), jsbsim_fcs.YAW_RATE))
        return {"gain_per_radps": {"row": "mach", "row_breakpoints": damper["mach"],
                                   "values": [g if abs(g) > 1e-12 else 0.0 for g in damper["gain_per_radps"]]},
                "engaged_at_start": True}

    def _find_wing_leveller(self, aileron_prop):
        """The first autopilot's wing leveller acting on the aileron (jsbsim_autopilot), its
        findings in place of the autopilots' placeholder notes."""
        found, reasons = None, {}
        fc = self.root.find("flight_control")
        for label, path, root, _ in self.autopilots:
            if root is None or found:
                continue
            defaults = jsbsim_autopilot.property_defaults(root, fc)
            try:
                found = jsbsim_autopilot.find(root, self.fcs, aileron_prop, defaults)
                found.label, found.file, found.root = label, path, root
            except jsbsim_autopilot.NotTranslated as e:
                reasons[label] = str(e)
        self._place_autopilot_notes(found, reasons)
        return found

    def _place_autopilot_notes(self, found, reasons):
        for label, _, root, placeholder in self.autopilots:
            if placeholder not in self.notes:
                continue
            at = self.notes.index(placeholder)
            if found is not None and found.label == label:
                self.notes[at:at + 1] = self._wing_leveller_notes(found)
            elif root is not None:
                why = reasons.get(label, "the pack has no aileron" if found is None else
                                  "the wing leveller comes from another autopilot")
                self.notes[at] = "%s: no wing leveller (%s)" % (placeholder, why)

    def _wing_leveller_notes(self, w):
        """What of the autopilot the pack carries, what it leaves out, and where fedsim's wing
        leveller departs from JSBSim's PID."""
        parts = jsbsim_autopilot.parts_of(w.root)
        used = {p.name for p in [w.pid] + w.switches + ([w.trigger] if w.trigger else [])}
        channels, sensors = [], []
        for channel in dict.fromkeys(p.channel for p in parts):
            members = [p for p in parts if p.channel == channel]
            on = [p.name for p in members if p.name in used]
            off = [p for p in members if p.name not in used]
            sensors += [p for p in off if p.type == "sensor"]
            if not on:
                channels.append("'%s'" % channel)
            elif any(p.type != "sensor" for p in off):
                channels.append("'%s' (all but %s, on the wing leveller's path)" %
                                (channel, ", ".join("'%s'" % n for n in on)))
        head = "JSBSim <autopilot> '%s'" % w.label
        notes = ["%s: its wing leveller (<pid> '%s' on %s, through %s to %s of FCS summer '%s') is "
                 "translated as flight_controls.wing_leveller, engaged by the pilot's wing-leveller "
                 "switch (fedsim's for JSBSim's %s)%s" % (
                     head, w.pid.name, jsbsim_autopilot.BANK,
                     ", ".join("switch '%s'" % p.name for p in w.switches), w.fcs_input,
                     w.summer.name, w.engage,
                     ("; not translated: channel%s %s" % ("s" if len(channels) > 1 else "",
                                                          ", ".join(channels))) if channels else "")]
        for sensor in sensors:
            what = [c.tag for c in sensor.element if c.tag not in ("input", "output")]
            notes.append("%s: sensor '%s'%s is not on the wing leveller's path (its PID reads %s) "
                         "and is not translated" % (
                             head, sensor.name, " (%s)" % ", ".join(what) if what else "",
                             jsbsim_autopilot.BANK))
        differences = []
        if w.trigger is not None or not w.trigger_name:
            differences.append("fedsim stops the integral while the summed aileron command is "
                               "saturated (JSBSim's PID '%s' has no anti-windup here)" % w.pid.name)
        else:
            differences.append("the PID's trigger %s is not translated (fedsim resets the integral "
                               "while disengaged and stops it while the summed aileron command is "
                               "saturated)" % w.trigger_name)
        if not w.trigger_name:
            differences.append("JSBSim's PID has no trigger, so its integral is never reset; "
                               "fedsim's is reset while disengaged")
        if w.rate_from is None:
            differences.append("fedsim uses the Euler-angle rate dphi/dt for the D term where "
                               "JSBSim takes the backward difference of phi between frames")
        if w.gains["ki"][0] != 0.0 and w.integration != "rect":
            differences.append("fedsim integrates by the rectangular rule, JSBSim by %s (%s): the "
                               "same in the limit of small steps" % (
                                   jsbsim_autopilot.INTEGRATION_RULES.get(w.integration, w.integration),
                                   "its default for a <ki> without type" if w.integration_default
                                   else "<ki type=\"%s\">" % w.integration))
        if w.wow and w.trigger is not None:
            differences.append("JSBSim's integral runs on the ground while engaged (its trigger "
                               "tests only %s), fedsim's is reset there (airborne_only)" % w.engage)
        notes.append("flight_controls.wing_leveller: " + "; ".join(differences))
        if w.negated:
            notes.append("flight_controls.wing_leveller: the path passes +'%s' (the aileron gets "
                         "+(Kp phi + ...)), so the pack's gains are JSBSim's negated" % w.pid.name)
        return notes

    def _wing_leveller_entry(self, w):
        """fedsim's wing_leveller section: command = -(Kp phi + Ki integral(phi) + Kd dphi/dt)."""
        flip = -1.0 if w.negated else 1.0
        where = " (%s '%s')" % (os.path.basename(w.file) if w.file else "<autopilot>", w.pid.name)
        out = {}
        for key, tag in (("bank_gain_per_rad", "kp"), ("bank_integral_gain_per_rad_s", "ki"),
                         ("bank_rate_gain_per_radps", "kd")):
            value, text = w.gains[tag]
            comment = ("minus " if w.negated and value != 0.0 else "") + text + \
                (where if tag == "kp" else "")
            out[key] = Commented(flip * value if value != 0.0 else 0.0, comment)
        out["airborne_only"] = Commented(bool(w.wow), "; ".join(
            "'%s' tests %s == 0" % (name, prop) for name, prop in w.wow) if w.wow else
            "no switch on the path tests gear WOW")
        out["engaged_at_start"] = Commented(w.engaged_at_start, "JSBSim %s starts at %g" % (
            w.engage, 1.0 if w.engaged_at_start else 0.0))
        return out

    def _aileron_candidates(self):
        """The fcs property the aerodynamics read for roll control: any aero-used fcs property
        without a fixed meaning that moves with the aileron command."""
        fixed = set(jsbsim_aero.VARIABLES)
        out = []
        for prop in sorted(self.aero_properties):
            if prop.startswith("fcs/") and prop not in fixed and self.fcs is not None:
                if abs(self.fcs.run({"fcs/aileron-cmd-norm": 1.0}).get(prop, 0.0)) > 0.0:
                    out.append(prop)
        if len(out) > 1:
            self.notes.append("several aileron properties %s: the pack uses %s" % (out, out[0]))
        return out

    @staticmethod
    def _unit_factor(prop):
        """JSBSim property value per radian."""
        return R2D if prop.endswith("-deg") else 1.0

    def _surface_entry(self, s, k):
        deg = R2D / k
        e = {"deflection_at_plus_one_deg": s["plus"] * deg,
             "deflection_at_minus_one_deg": s["minus"] * deg}
        if s["clip_max"] < max(s["plus"], s["minus"]) - 1e-12:
            e["max_deflection_deg"] = s["clip_max"] * deg
        if s["clip_min"] > min(s["plus"], s["minus"]) + 1e-12:
            e["min_deflection_deg"] = s["clip_min"] * deg
        if s["lag"] > 0.0:
            e["time_constant_s"] = Commented(s["lag"], "JSBSim actuator lag %g /s" % (1.0 / s["lag"]))
        if s["rate"] > 0.0:
            e["rate_limit_deg_per_s"] = Commented(s["rate"] * deg, "%g rad/s" % (s["rate"] * deg / R2D))
        return e

    def _kinematic_entry(self, prop, is_flap):
        settings = self.fcs.kinematic_for(prop) if self.fcs else None
        if settings is None:
            self.notes.append("%s is not driven by a kinematic component: left out" % prop)
            return None
        positions, times = settings
        full = positions[-1]
        e = {"positions_norm": [p / full for p in positions], "transit_times_s": times[1:]}
        if is_flap and not prop.endswith("-norm"):
            e["full_travel_deg"] = full if prop.endswith("-deg") else full * R2D
        return e

    # -- aerodynamics -------------------------------------------------------------------------
    def aerodynamics(self):
        extra = {}
        if "aileron" in self.surfaces:
            prop, _, k = self.surfaces["aileron"]
            extra[prop] = ("aileron_rad", k)
        self.translator = jsbsim_aero.AeroTranslator(self.aero_element, extra, self.notes)
        axes = self.translator.axes()
        out = {}
        hyst = self.aero_element.find("hysteresis_limits")
        if hyst is not None:
            unit = hyst.get("unit", "RAD")
            out["stall_hysteresis"] = {
                "alpha_set_rad": jx.to_si(float(hyst.findtext("max")), unit),
                "alpha_clear_rad": jx.to_si(float(hyst.findtext("min")), unit)}
        factors = self.translator.factor_terms()
        if factors:
            out["factors"] = factors
        out.update(axes)
        self.aero_axes, self.aero_factors = axes, factors
        return out

    # -- propulsion ---------------------------------------------------------------------------
    def _engine_root(self, engine):
        path = os.path.join(self.engine_dir, engine.get("file") + ".xml")
        if path not in self.files_read:
            self.files_read.append(path)
        return jx.parse(path)

    def propulsion(self):
        prop = self.root.find("propulsion")
        engines = []
        for i, engine in enumerate(prop.findall("engine")):
            eroot = self._engine_root(engine)
            thruster = engine.find("thruster")
            troot = self._engine_root(thruster)
            loc = thruster.find("location")
            pos = jx.structural_to_pack(loc)
            side = "left" if pos[1] < 0 else ("right" if pos[1] > 0 else "centre")
            e = {"name": "engine %d %s" % (i + 1, side) if len(prop.findall("engine")) > 1 else "engine"}
            e["type"] = "turbofan" if eroot.tag == "turbine_engine" else "piston_propeller"
            e["position_m"] = Commented(pos, xyz_text(loc))
            orient = thruster.find("orient")
            if orient is not None:
                unit = orient.get("unit", "RAD")
                e["orientation_deg"] = [jx.to_si(float(orient.findtext(a)), unit) * R2D
                                        for a in ("roll", "pitch", "yaw")]
            e["fuel_tanks"] = [int(f.text) for f in engine.findall("feed")]
            if eroot.tag == "piston_engine" and troot.tag == "propeller":
                e["piston"] = self._piston(eroot)
                e["propeller"] = self._propeller(troot, thruster)
            elif eroot.tag == "turbine_engine" and troot.tag == "direct":
                e["turbofan"] = self._turbofan(eroot)
            else:
                self.notes.append("engine %d (%s with %s) is not translated" % (i, eroot.tag, troot.tag))
                continue
            engines.append(e)
        return {"engines": engines}

    def _note_unknown(self, element, known, what):
        for child in element:
            if child.tag not in known:
                self.notes.append("%s: <%s> is not translated" % (what, child.tag))

    def _piston(self, p):
        self._note_unknown(p, {"minmp", "maxmp", "displacement", "maxhp", "bsfc", "cycles", "idlerpm",
                               "maxrpm", "maxthrottle", "minthrottle", "sparkfaildrop"}, "piston engine")
        lb_per_hp_h = jx.LB_MASS / (jx.UNITS["HP"] / 1000.0)  # kg/kWh per lb/(hp h)
        return {
            "max_power_w": Commented(jx.value_si(p, "maxhp", "HP"), "%s hp" % p.findtext("maxhp").strip()),
            "displacement_m3": commented(jx.value_si(p, "displacement", "IN3"), p.find("displacement"), "IN3"),
            "idle_rpm": jx.plain_number(p, "idlerpm"),
            "max_rpm": jx.plain_number(p, "maxrpm"),
            "min_manifold_pressure_pa": commented(jx.value_si(p, "minmp", "INHG"), p.find("minmp"), "INHG"),
            "max_manifold_pressure_pa": commented(jx.value_si(p, "maxmp", "INHG"), p.find("maxmp"), "INHG"),
            "bsfc_kg_per_kwh": Commented(jx.plain_number(p, "bsfc") * lb_per_hp_h,
                                         "%s lb/(hp h)" % p.findtext("bsfc").strip()),
            "strokes": int(jx.plain_number(p, "cycles", 4.0)),
            "min_throttle": jx.plain_number(p, "minthrottle", 0.1),
            "max_throttle": jx.plain_number(p, "maxthrottle", 1.0),
            "single_magneto_power_loss": jx.plain_number(p, "sparkfaildrop", 0.0)}

    def _propeller(self, p, thruster):
        self._note_unknown(p, {"ixx", "diameter", "numblades", "minpitch", "maxpitch", "gearratio",
                               "ct_factor", "cp_factor", "table"}, "propeller")
        tables = {t.get("name"): t for t in p.findall("table")}
        out = {"diameter_m": commented(jx.value_si(p, "diameter", "FT"), p.find("diameter"), "FT"),
               "blade_count": int(jx.plain_number(p, "numblades")),
               "inertia_kgm2": commented(jx.value_si(p, "ixx", "SLUG*FT2"), p.find("ixx"), "SLUG*FT2"),
               "gear_ratio": jx.plain_number(p, "gearratio", 1.0),
               "min_pitch_deg": jx.plain_number(p, "minpitch"),
               "max_pitch_deg": jx.plain_number(p, "maxpitch"),
               "spin_sense": int(jx.plain_number(thruster, "sense", 1.0)),
               "p_factor_m_per_rad": Commented(jx.plain_number(thruster, "p_factor", 0.0) * jx.IN,
                                               "%g in/rad" % jx.plain_number(thruster, "p_factor", 0.0))}
        for key, name in (("thrust_coefficient", "C_THRUST"), ("power_coefficient", "C_POWER")):
            if name in tables:
                out[key] = internal_table(tables[name], "advance_ratio", "blade_pitch_deg")
        # JSBSim FGPropeller multiplies C_THRUST by <ct_factor> and C_POWER by <cp_factor>.
        for key, element in (("thrust_coefficient_factor", "ct_factor"),
                             ("power_coefficient_factor", "cp_factor")):
            if p.find(element) is not None:
                out[key] = Commented(jx.plain_number(p, element), "JSBSim <%s>" % element)
        for key, name in (("thrust_tip_mach_factor", "CT_MACH"), ("power_tip_mach_factor", "CP_MACH")):
            if name in tables:
                out[key] = internal_table(tables[name], "tip_mach", None)
        for name in tables:
            if name not in ("C_THRUST", "C_POWER", "CT_MACH", "CP_MACH"):
                self.notes.append("propeller table %s is not translated" % name)
        return out

    def _turbofan(self, t):
        self._note_unknown(t, {"milthrust", "bypassratio", "tsfc", "bleed", "idlen1", "idlen2", "maxn1",
                               "maxn2", "augmented", "injected", "function"}, "turbine engine")
        for flag in ("augmented", "injected"):
            if jx.plain_number(t, flag, 0.0) != 0.0:
                self.notes.append("turbine engine: %s = 1 is not supported" % flag)
        functions = {f.get("name"): f for f in t.findall("function")}
        out = {"max_thrust_n": Commented(jx.plain_number(t, "milthrust") * jx.LBF,
                                         "%s lbf" % t.findtext("milthrust").strip()),
               "bypass_ratio": jx.plain_number(t, "bypassratio"),
               "tsfc_kg_per_n_h": Commented(jx.plain_number(t, "tsfc") * jx.LB_MASS / jx.LBF,
                                            "%s lb/(lbf h)" % t.findtext("tsfc").strip()),
               "bleed_fraction": jx.plain_number(t, "bleed", 0.0),
               "idle_n1_pct": jx.plain_number(t, "idlen1"),
               "idle_n2_pct": jx.plain_number(t, "idlen2"),
               "max_n1_pct": jx.plain_number(t, "maxn1", 100.0),
               "max_n2_pct": jx.plain_number(t, "maxn2", 100.0)}
        out.update(self._spool_time_constants(out))
        idle_ff_lb_per_h = (out["max_thrust_n"].value / jx.LBF) ** 0.2 * 107.0
        out["min_fuel_flow_kg_per_s"] = Commented(idle_ff_lb_per_h * jx.LB_MASS / 3600.0,
                                                  "JSBSim IdleFF = milthrust^0.2 * 107 = %.0f lb/h"
                                                  % idle_ff_lb_per_h)
        for key, name in (("idle_thrust_fraction", "IdleThrust"), ("max_thrust_fraction", "MilThrust")):
            out[key] = thrust_table(functions[name])
        for name in functions:
            if name not in ("IdleThrust", "MilThrust"):
                self.notes.append("turbine function %s is not translated" % name)
        return out

    def _spool_time_constants(self, t):
        """JSBSim's turbine spools at delay = 90 / (bypass ratio + 3) %/s (N2 and N1 up; N2
        down 3x, N1 down 2.4x faster; FGTurbine::Run). As first-order lags: the time constant
        that covers 95 % (three time constants) of the idle-to-max range in the time the
        JSBSim ramp takes at that rate."""
        rate = 90.0 / (t["bypass_ratio"] + 3.0)
        n1_range = t["max_n1_pct"] - t["idle_n1_pct"]
        n2_range = t["max_n2_pct"] - t["idle_n2_pct"]
        note = "from JSBSim's spool rate 90/(BPR+3) = %.3g %%/s" % rate
        self.notes.append("turbofan spool time constants derived from JSBSim's spool rate "
                          "90/(bypass ratio + 3) %/s (no such figures in the engine file)")
        return {"n1_spool_up_time_constant_s": Commented(n1_range / (3 * rate), note),
                "n1_spool_down_time_constant_s": Commented(n1_range / (3 * 2.4 * rate), "x 2.4 down"),
                "n2_spool_up_time_constant_s": Commented(n2_range / (3 * rate), note),
                "n2_spool_down_time_constant_s": Commented(n2_range / (3 * 3.0 * rate), "x 3 down")}

    # -- landing gear -------------------------------------------------------------------------
    def landing_gear(self):
        gr = self.root.find("ground_reactions")
        contacts = [self._contact(c, i) for i, c in enumerate(gr.findall("contact"))] if gr is not None else []
        out = {}
        settings = self.fcs.kinematic_for("gear/gear-pos-norm") if self.fcs else None
        if settings is not None:
            out["transit_time_s"] = sum(settings[1][1:])
        elif any(c.get("retractable") for c in contacts):
            self.notes.append("retractable gear without a gear kinematic: transit time 5 s assumed")
            out["transit_time_s"] = 5.0
        out["contacts"] = contacts
        return out

    def _contact(self, c, index):
        wheel = c.get("type", "BOGEY").upper() == "BOGEY"
        self._note_unknown(c, {"location", "static_friction", "dynamic_friction", "rolling_friction",
                               "spring_coeff", "damping_coeff", "damping_coeff_rebound", "max_steer",
                               "brake_group", "retractable", "strut_force"}, "contact '%s'" % c.get("name"))
        loc = c.find("location")
        e = {"name": c.get("name").strip().lower().replace("_", " "),
             "type": "wheel" if wheel else "structure",
             "position_m": Commented(jx.structural_to_pack(loc), xyz_text(loc))}
        spring, damping, rebound = self._strut(c, index)
        e["spring_n_per_m"] = Commented(spring * jx.UNITS["LBS/FT"], "%g lbf/ft" % spring)
        e["damping_n_s_per_m"] = Commented(damping * jx.UNITS["LBS/FT/SEC"], "%g lbf/(ft/s)" % damping)
        if rebound != damping:
            e["rebound_damping_n_s_per_m"] = Commented(rebound * jx.UNITS["LBS/FT/SEC"],
                                                       "%g lbf/(ft/s)" % rebound)
        e["static_friction"] = jx.plain_number(c, "static_friction")
        e["dynamic_friction"] = jx.plain_number(c, "dynamic_friction")
        if wheel:
            e["rolling_friction"] = jx.plain_number(c, "rolling_friction", 0.0)
            steer = c.find("max_steer")
            if steer is not None and float(steer.text) != 0.0:
                e["max_steer_deg"] = jx.to_si(float(steer.text), steer.get("unit", "DEG")) * R2D
            group = (c.findtext("brake_group") or "NONE").strip().upper()
            mapped = {"NONE": "none", "LEFT": "left", "RIGHT": "right"}.get(group)
            if mapped is None:
                self.notes.append("contact '%s': brake group %s is not modelled (no brake)" %
                                  (c.get("name"), group))
                mapped = "none"
            if mapped != "none":
                e["brake_group"] = mapped
            if jx.plain_number(c, "retractable", 0.0) != 0.0:
                e["retractable"] = True
        return e

    def _strut(self, c, index):
        """Spring and damping (lbf/ft, lbf/(ft/s)) of a contact, from its coefficients or by
        probing a <strut_force> function (force = -k x - c v, c depending on the sign of v)."""
        function = c.find("strut_force")
        if function is None:
            spring_e = c.find("spring_coeff")
            spring = jx.to_si(float(spring_e.text), spring_e.get("unit", "LBS/FT")) / jx.UNITS["LBS/FT"]
            damping = jx.value_si(c, "damping_coeff", "LBS/FT/SEC") / jx.UNITS["LBS/FT/SEC"]
            rebound = jx.value_si(c, "damping_coeff_rebound", "LBS/FT/SEC", damping * jx.UNITS["LBS/FT/SEC"])
            return spring, damping, rebound / jx.UNITS["LBS/FT/SEC"]
        fn = function.find("function")
        base = "gear/unit[%d]/" % index

        def force(x_ft, v_fps):
            return jx.evaluate(fn, {base + "compression-ft": x_ft, base + "compression-velocity-fps": v_fps})

        spring, damping, rebound = -force(1.0, 0.0), -force(0.0, 1.0), force(0.0, -1.0)
        linear = (abs(force(2.0, 0.0) + 2 * spring) < 1e-9 * spring and
                  abs(force(0.0, 2.0) + 2 * damping) < 1e-9 * max(damping, 1.0) and
                  abs(force(1.0, 1.0) + spring + damping) < 1e-9 * spring)
        if not linear:
            self.notes.append("contact '%s': strut_force is not a linear spring-damper; the pack "
                              "keeps its slopes at 1 ft and 1 ft/s" % c.get("name"))
        else:
            self.notes.append("contact '%s': strut_force function read as spring %g lbf/ft, damping "
                              "%g / %g lbf/(ft/s)" % (c.get("name"), spring, damping, rebound))
        return spring, damping, rebound

    # -- limits -----------------------------------------------------------------------------
    def limits(self):
        out = {}
        lim = self.aero_element.find("alphalimits")
        if lim is not None:
            unit = lim.get("unit", "RAD")
            out["alpha_min_rad"] = jx.to_si(float(lim.findtext("min")), unit)
            out["alpha_max_rad"] = jx.to_si(float(lim.findtext("max")), unit)
        return out

    # -- checks -----------------------------------------------------------------------------
    def control_sign_report(self):
        """Moment coefficient per fedsim command +1 at zero alpha, from the translated terms."""
        lines = []
        checks = (("elevator", "elevator_rad", "pitch_moment", "Cm", -1),
                  ("aileron", "aileron_rad", "roll_moment", "Cl", 1),
                  ("rudder", "rudder_rad", "yaw_moment", "Cn", 1))
        for surface, variable, axis, name, expected in checks:
            if surface not in self.surfaces:
                continue
            _, s, k = self.surfaces[surface]
            env0 = {"h_over_b": 10.0}
            env1 = dict(env0, **{variable: s["plus"] / k, "abs_" + variable: abs(s["plus"] / k)})
            delta = (jsbsim_aero.evaluate_axis(self.aero_axes[axis], self.aero_factors, env1) -
                     jsbsim_aero.evaluate_axis(self.aero_axes[axis], self.aero_factors, env0))
            ok = delta * expected > 0
            lines.append("%s command +1 -> %s change %+.4f (%s)" %
                         (surface, name, delta, "as DESIGN.md" if ok else "WRONG SIGN"))
            if not ok:
                self.notes.append("%s command +1 gives %s %+.4f, against fedsim's convention" %
                                  (surface, name, delta))
        return lines


def internal_table(element, row_name, column_name):
    """A JSBSim propeller table without independentVar: 1-D (x y per line) or 2-D (first line
    the column breakpoints)."""
    lines = [l.split() for l in element.find("tableData").text.strip().splitlines() if l.split()]
    if all(len(l) == 2 for l in lines):
        return {"row": row_name, "row_breakpoints": [float(l[0]) for l in lines],
                "values": [float(l[1]) for l in lines]}
    if column_name is None:
        raise ValueError("table %s should be 1-D" % element.get("name"))
    return {"row": row_name, "column": column_name,
            "row_breakpoints": [float(l[0]) for l in lines[1:]],
            "column_breakpoints": [float(v) for v in lines[0]],
            "values": [[float(v) for v in l[1:]] for l in lines[1:]]}


def thrust_table(function):
    table = jx.JsbTable(jx.function_body(function))
    if table.lookup_order() != ["velocities/mach", "atmosphere/density-altitude"]:
        raise ValueError("turbine table %s: unexpected inputs %s" %
                         (function.get("name"), table.lookup_order()))
    return {"row": "mach", "column": "density_altitude_m", "row_breakpoints": table.rows,
            "column_breakpoints": [h * jx.FT for h in table.cols], "values": table.values}


def relative(path, root):
    return os.path.relpath(os.path.abspath(path), os.path.abspath(root)) if root else os.path.basename(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("aircraft", help="JSBSim aircraft XML file")
    parser.add_argument("--output", "-o", required=True, help="fedsim pack to write (YAML)")
    parser.add_argument("--jsbsim-root", help="root of the JSBSim tree (for relative file names "
                        "and the default engine folder)")
    parser.add_argument("--engine-dir", help="folder of engine and propeller files")
    parser.add_argument("--commit", default="", help="JSBSim commit the files come from")
    parser.add_argument("--name", help="pack name (default: the aircraft file's name attribute)")
    parser.add_argument("--calibration", help="calibration overlay to merge (e.g. "
                        "data/aircraft/c172.calibration.yaml; its 'pack' must name the output)")
    parser.add_argument("--pitch-trim", metavar="KIND:RATE",
                        help="a pitch trim with a trim rate (JSBSim gives none): 'stabiliser' or "
                             "'tab', and the rate in normalised trim travel per second, e.g. "
                             "stabiliser:0.03")
    args = parser.parse_args(argv)
    pitch_trim = None
    if args.pitch_trim:
        try:
            kind, rate_text = args.pitch_trim.split(":")
            rate = float(rate_text)
            if kind not in ("stabiliser", "tab") or not (0.0 < rate <= 10.0):
                raise ValueError
        except ValueError:
            print("jsbsim2fedsim: --pitch-trim must be stabiliser:RATE or tab:RATE with 0 < RATE <= 10 "
                  "(got %r)" % args.pitch_trim, file=sys.stderr)
            return 1
        pitch_trim = (kind, rate)
    overlay = None
    if args.calibration:
        try:
            overlay = calibration.read_overlay(args.calibration, os.path.basename(args.output))
        except (OSError, calibration.CalibrationError) as e:
            print("jsbsim2fedsim: %s" % e, file=sys.stderr)
            return 1

    root_dir = args.jsbsim_root or os.path.join(os.path.dirname(args.aircraft), "..", "..")
    engine_dir = args.engine_dir or os.path.join(root_dir, "engine")
    notes = []
    conv = Converter(args.aircraft, engine_dir, notes, pitch_trim)
    sections = {}
    sections["fedsim_aircraft_pack"] = 1
    sections["metadata"] = None  # filled last, once every file read is known
    sections["geometry"] = conv.geometry()
    sections["mass"] = conv.mass()
    sections["flight_controls"] = conv.flight_controls()
    sections["aerodynamics"] = conv.aerodynamics()
    sections["propulsion"] = conv.propulsion()
    sections["landing_gear"] = conv.landing_gear()
    sections["limits"] = conv.limits()
    checks = conv.control_sign_report()
    if overlay is not None:
        try:
            calibration.apply(overlay, sections, notes, Commented)
        except calibration.CalibrationError as e:
            print("jsbsim2fedsim: %s" % e, file=sys.stderr)
            return 1
    notes[:] = list(dict.fromkeys(notes))  # one line per distinct finding

    files = ", ".join(relative(f, args.jsbsim_root) for f in conv.files_read)
    commit = ("JSBSim-Team/jsbsim commit %s: " % args.commit) if args.commit else "JSBSim: "
    calibrated = ("; calibrated by " + os.path.basename(args.calibration)) if overlay else ""
    metadata = {"name": args.name or conv.root.get("name"),
                "source": commit + files + "; converted by tools/jsbsim2fedsim" + calibrated}
    description = conv.root.findtext("fileheader/description")
    if description:
        metadata["description"] = " ".join(description.split())
    if notes:
        metadata["notes"] = notes
    sections["metadata"] = metadata
    header = ["fedsim aircraft pack generated by tools/jsbsim2fedsim/jsbsim2fedsim.py",
              "from JSBSim " + files,
              "(figures only; see metadata.source). Regenerate rather than edit; the format is",
              "documented in data/aircraft/README.md. Comments give the JSBSim figure each SI",
              "value came from (JSBSim structural frame: x aft, y right, z up)."]
    if overlay is not None:
        header += ["Values marked 'calibrated' come from %s (merged with --calibration):" %
                   os.path.basename(args.calibration),
                   "identified from published performance; edit that file, not this one."]
    with open(args.output, "w") as out:
        out.write(document(header, sections))
    for line in checks:
        print("check: " + line, file=sys.stderr)
    for note in notes:
        print("note: " + note, file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
