"""Static (steady-state) evaluation of a JSBSim <flight_control> block.

A fedsim pack describes each control surface by its travel for commands +1 and -1, a clip, a
lag and a rate limit. JSBSim builds the same thing from a chain of components (summers,
aerosurface_scale, actuators, kinematics...). Rather than pattern-matching chains, the
converter runs the chain in steady state for a few command values and reads the travel off
the result, then collects the dynamics of the actuators upstream of the surface.
"""

import jsbsim_xml as jx

SUPPORTED = ("summer", "pure_gain", "scheduled_gain", "aerosurface_scale", "actuator",
             "kinematic", "fcs_function")

# The body yaw rate a yaw damper feeds back (relative to the air mass) and the Mach number its
# gain is scheduled on.
YAW_RATE = "velocities/r-aero-rad_sec"
MACH = "velocities/mach"
# Components a static yaw-damper gain can pass through: gains and sums (no filters).
STATIC_GAINS = ("summer", "pure_gain", "scheduled_gain", "aerosurface_scale")


def _number_or_none(element, tag):
    child = element.find(tag)
    if child is None:
        return None
    try:
        return float(child.text)
    except ValueError:
        return None  # a property name: not a static figure


class Component:
    def __init__(self, element, notes):
        self.type = element.tag
        self.name = element.get("name", "")
        self.element = element
        self.outputs = [jx.property_name(self.name)] + [o.text.strip() for o in element.findall("output")]
        self.inputs = [i.text.strip() for i in element.findall("input")]
        clip = element.find("clipto")
        self.clip = None
        if clip is not None:
            low, high = _number_or_none(clip, "min"), _number_or_none(clip, "max")
            if low is None or high is None:
                notes.append("FCS %s '%s': clip limits given by properties are ignored" %
                             (self.type, self.name))
            else:
                self.clip = (low, high)
        if self.type not in SUPPORTED:
            notes.append("FCS component <%s> '%s' is not translated (its output reads 0 in the "
                         "static evaluation)" % (self.type, self.name))

    # -- steady-state output ------------------------------------------------------------
    def _input(self, env, index=0):
        name = self.inputs[index]
        sign = -1.0 if name.startswith("-") else 1.0
        return sign * env.get(name.lstrip("-"), 0.0)

    def output(self, env, clip):
        value = self._raw_output(env)
        if clip and self.clip is not None:
            value = min(max(value, self.clip[0]), self.clip[1])
        return value

    def _raw_output(self, env):
        e = self.element
        if self.type == "summer":
            return sum(self._input(env, i) for i in range(len(self.inputs))) + \
                (_number_or_none(e, "bias") or 0.0)
        if self.type == "pure_gain":
            return self._input(env) * (_number_or_none(e, "gain") or 1.0)
        if self.type == "scheduled_gain":
            return self._input(env) * jx.JsbTable(e.find("table"))(env)
        if self.type == "aerosurface_scale":
            return self._aerosurface_scale(env)
        if self.type == "actuator":
            return self._input(env) + (_number_or_none(e, "bias") or 0.0)
        if self.type == "kinematic":
            return self._kinematic(env)
        if self.type == "fcs_function":
            return jx.evaluate(e.find("function"), env)
        return 0.0

    def _aerosurface_scale(self, env):
        # JSBSim FGGain AEROSURFACE_SCALE: zero-centred maps [in_min, 0] -> [out_min, 0] and
        # [0, in_max] -> [0, out_max]; otherwise a straight line from min to max.
        e = self.element
        domain, rng = e.find("domain"), e.find("range")
        in_min = _number_or_none(domain, "min") if domain is not None else -1.0
        in_max = _number_or_none(domain, "max") if domain is not None else 1.0
        out_min = _number_or_none(rng, "min") if rng is not None else -1.0
        out_max = _number_or_none(rng, "max") if rng is not None else 1.0
        zc = e.find("zero_centered")
        zero_centered = zc is None or zc.text.strip().lower() not in ("0", "false")
        x = self._input(env)
        if zero_centered:
            if x == 0.0:
                y = 0.0
            elif x > 0.0:
                y = x / in_max * out_max
            else:
                y = x / in_min * out_min
        else:
            y = out_min + (x - in_min) / (in_max - in_min) * (out_max - out_min)
        return y * (_number_or_none(e, "gain") or 1.0)

    def kinematic_settings(self):
        settings = self.element.find("traverse").findall("setting")
        return ([float(s.find("position").text) for s in settings],
                [float(s.find("time").text) for s in settings])

    def _kinematic(self, env):
        positions, _ = self.kinematic_settings()
        x = self._input(env)
        if self.element.find("noscale") is None:
            x *= positions[-1]
        return min(max(x, positions[0]), positions[-1])

    # -- dynamics -----------------------------------------------------------------------
    def lag_time_constant_s(self):
        lag = _number_or_none(self.element, "lag") if self.type == "actuator" else None
        return 1.0 / lag if lag else 0.0

    def rate_limit(self):
        if self.type != "actuator":
            return 0.0
        return _number_or_none(self.element, "rate_limit") or 0.0


class StaticFcs:
    def __init__(self, flight_control, notes):
        self.components = []
        for channel in flight_control.findall("channel"):
            for element in channel:
                self.components.append(Component(element, notes))
        self.producer = {}
        for c in self.components:
            for out in c.outputs:
                self.producer[out] = c

    def run(self, commands, clip=True, offsets=None):
        """Steady-state property values for the given command properties. `offsets` adds a
        value to chosen components' outputs (to measure sensitivities)."""
        env = dict(commands)
        for c in self.components:
            value = c.output(env, clip)
            if offsets and c.name in offsets:
                value += offsets[c.name]
            for out in c.outputs:
                env[out] = value
        return env

    def upstream(self, prop):
        """Components that feed `prop`, nearest first."""
        seen, order, todo = set(), [], [prop]
        while todo:
            name = todo.pop(0).lstrip("-")
            c = self.producer.get(name)
            if c is None or id(c) in seen:
                continue
            seen.add(id(c))
            order.append(c)
            todo.extend(c.inputs)
        return order

    def traces_to(self, component, prop, seen=None):
        """True when `component`'s inputs lead (through other components) to `prop`."""
        seen = set() if seen is None else seen
        if id(component) in seen:
            return False
        seen.add(id(component))
        for name in (i.lstrip("-") for i in component.inputs):
            if name == prop:
                return True
            c = self.producer.get(name)
            if c is not None and self.traces_to(c, prop, seen):
                return True
        return False

    def yaw_damper(self, prop, command_prop, command_sign, notes):
        """The yaw damper feeding `prop` (the rudder position) from the body yaw rate, as a
        fedsim gain table: normalised rudder command per rad/s against Mach, at the Mach
        breakpoints of the schedules on its path. None when the chain has no yaw-rate input, or
        when the path holds anything but static gains and sums (filters are not translated)."""
        path = [c for c in self.upstream(prop) if self.traces_to(c, YAW_RATE)]
        if not path:
            return None
        if any(c.type not in STATIC_GAINS for c in path):
            notes.append("%s: the yaw damper path holds %s: not translated" %
                         (prop, ", ".join("<%s> '%s'" % (c.type, c.name) for c in path
                                          if c.type not in STATIC_GAINS)))
            return None
        machs = set()
        for c in path:
            if c.type == "scheduled_gain":
                table = jx.JsbTable(c.element.find("table"))
                if table.dimensions != 1 or table.variables.get("row") != MACH:
                    notes.append("%s: yaw damper gain '%s' is scheduled on %s: not translated" %
                                 (prop, c.name, table.variables))
                    return None
                machs.update(table.rows)
        machs = sorted(machs) or [0.0, 1.0]
        full = self.run({command_prop: command_sign * 1.0}, False)[prop]
        rate = 1e-3  # rad/s: small, the chain is linear in it
        gains = []
        for m in machs:
            moved = self.run({command_prop: 0.0, YAW_RATE: rate, MACH: m}, False)[prop]
            rest = self.run({command_prop: 0.0, YAW_RATE: 0.0, MACH: m}, False)[prop]
            gains.append((moved - rest) / full / rate)
        return {"mach": machs, "gain_per_radps": gains,
                "components": [c.name for c in path if c.type in ("pure_gain", "scheduled_gain")]}

    def surface(self, prop, command_prop, command_sign, notes, translated=(), translated_inputs=()):
        """Travel, clip and dynamics of property `prop` driven by `command_prop`; a fedsim
        command c sets the JSBSim command to command_sign * c. Components fed by one of the
        `translated` properties (a yaw damper on the yaw rate) are not reported as left out,
        nor are the `translated_inputs` (an autopilot output the pack carries)."""
        def value(c, clip):
            return self.run({command_prop: command_sign * c}, clip)[prop]

        plus, minus = value(1.0, False), value(-1.0, False)
        for c in (0.5, -0.5, 0.25, -0.25):
            expected = abs(c) * (plus if c > 0 else minus)
            if abs(value(c, False) - expected) > 1e-9 * max(1.0, abs(expected)):
                notes.append("%s is not piecewise linear in %s: the pack keeps the travel at "
                             "+-1 only" % (prop, command_prop))
                break
        clipped_plus, clipped_minus = value(1.0, True), value(-1.0, True)
        self._note_outside_inputs(prop, command_prop, notes, translated, translated_inputs)
        actuators = [c for c in self.upstream(prop) if c.type == "actuator"]
        rate, lag = 0.0, 0.0
        for act in actuators:
            # The surface moves at the sum of |d prop / d actuator| * rate over its actuators
            # (e.g. 0.5 (left - right) of two ailerons moves at one aileron's rate).
            base = self.run({command_prop: 0.0}, True)[prop]
            bumped = self.run({command_prop: 0.0}, True, {act.name: 1e-3})[prop]
            sensitivity = abs(bumped - base) / 1e-3
            rate += sensitivity * act.rate_limit()
            lag = max(lag, act.lag_time_constant_s())
        if any(a.rate_limit() == 0.0 for a in actuators) and rate > 0.0:
            notes.append("%s: some of its actuators have no rate limit; the pack uses the "
                         "limited ones" % prop)
        return {"plus": plus, "minus": minus, "clip_max": max(clipped_plus, clipped_minus),
                "clip_min": min(clipped_plus, clipped_minus), "rate": rate, "lag": lag,
                "actuators": [a.name for a in actuators]}

    def _note_outside_inputs(self, prop, command_prop, notes, translated=(), translated_inputs=()):
        """Inputs of the chain other than pilot commands and trims (autopilot outputs, yaw
        dampers fed by body rates...) are feedback laws the pack cannot carry, unless
        translated (the yaw damper, the wing leveller's autopilot output)."""
        def carried(c):
            return any(self.traces_to(c, t) for t in translated)
        for c in self.upstream(prop):
            if carried(c):
                continue
            for name in (i.lstrip("-") for i in c.inputs):
                pilot = name == command_prop or (name.startswith("fcs/") and name.endswith("-cmd-norm"))
                if name not in self.producer and not pilot and name not in translated_inputs:
                    notes.append("%s: input %s of FCS %s '%s' is not translated (read as 0)" %
                                 (prop, name, c.type, c.name))
        for c in self.upstream(prop):
            if c.type == "scheduled_gain" and not carried(c):
                notes.append("%s: scheduled gain '%s' (%s) is not translated" %
                             (prop, c.name, ", ".join(c.inputs)))

    def kinematic_for(self, prop):
        c = self.producer.get(prop)
        if c is None or c.type != "kinematic":
            return None
        return c.kinematic_settings()
