"""The wing leveller of a JSBSim <autopilot>: a <pid> on the bank angle whose output, passed
by switches on an engage property, is summed with the pilot's aileron command in the FCS.

The chain is found by what it reads and writes, not by component names: a <pid> whose input
is attitude/phi-rad, then the switches that pass it (each test a plain AND of
`property == number` conditions: `P == 1` is the engage switch, `gear/unit[i]/WOW == 0` means
airborne only), up to a property that an FCS summer on the aileron chain adds to the pilot's
fcs/aileron-cmd-norm. Whatever does not fit is the reason no wing leveller is written.
"""

import re

import jsbsim_xml as jx

BANK = "attitude/phi-rad"
EULER_BANK_RATE = "velocities/phidot-rad_sec"  # a <pvdot> that is fedsim's dphi/dt
PILOT_AILERON = "fcs/aileron-cmd-norm"
WOW = re.compile(r"^gear/unit(\[\d+\])?/WOW$")
CONDITION = re.compile(r"^(\S+)\s*(==|eq|EQ)\s*(\S+)$")
NOT_COMPONENTS = ("property", "description", "documentation")
SWITCH_PARTS = ("default", "test", "output", "description")
# JSBSim FGPID integrates by its <ki type="..."> rule; without one (or another), 2nd-order
# Adams-Bashforth.
INTEGRATION_RULES = {"rect": "the rectangular rule", "trap": "the trapezoidal rule",
                     "ab2": "2nd-order Adams-Bashforth", "ab3": "3rd-order Adams-Bashforth"}


class NotTranslated(Exception):
    """Why the autopilot's wing leveller cannot be carried by the pack."""


def signed(text):
    """(sign, property) of a JSBSim input such as '-fcs/x'."""
    t = text.strip()
    return (-1.0, t[1:].strip()) if t.startswith("-") else (1.0, t)


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def property_defaults(*elements):
    """Initial values of the `<property value="...">` declarations directly under elements."""
    out = {}
    for e in elements:
        if e is None:
            continue
        for p in e.findall("property"):
            if p.get("value") is not None and p.text:
                out[p.text.strip()] = float(p.get("value"))
    return out


class Part:
    """One autopilot component: what it writes and reads."""

    def __init__(self, element, channel):
        self.element, self.type, self.channel = element, element.tag, channel
        self.name = jx.property_name(element.get("name", ""))
        self.outputs = [self.name] + [o.text.strip() for o in element.findall("output")]
        self.inputs = [i.text.strip() for i in element.findall("input")]

    def reads(self, names):
        return any(signed(i)[1] in names for i in self.inputs)


def parts_of(autopilot):
    return [Part(e, channel.get("name", "")) for channel in autopilot.findall("channel")
            for e in channel if e.tag not in NOT_COMPONENTS]


def conditions(test):
    """A switch <test>'s conditions as (property, value) pairs: a plain AND of
    `property == number` lines, else NotTranslated."""
    lines = [l.strip() for l in (test.text or "").splitlines() if l.strip()]
    logic = test.get("logic", "AND").upper()
    out = []
    for line in lines:
        m = CONDITION.match(line)
        value = number(m.group(3)) if m else None
        if value is None:
            raise NotTranslated("condition '%s' is not 'property == number'" % line)
        out.append((m.group(1), value))
    if len(test) or (logic != "AND" and len(out) > 1) or not out:
        raise NotTranslated("a test is not a plain AND of conditions")
    return out


class WingLeveller:
    """The result: gains with the JSBSim text each came from, and what the chain used."""

    def __init__(self, **kw):
        self.__dict__.update(kw)


def find(autopilot, fcs, aileron_prop, defaults):
    """The wing leveller of `autopilot` (an <autopilot> root) acting on `aileron_prop` through
    the StaticFcs `fcs`; `defaults` are the properties' initial values. NotTranslated when
    there is none; the first <pid> on the bank that reaches the aileron wins."""
    parts = parts_of(autopilot)
    pids = [p for p in parts if p.type == "pid" and len(p.inputs) == 1
            and signed(p.inputs[0])[1] == BANK]
    if not pids:
        raise NotTranslated("no <pid> reads %s" % BANK)
    reasons = []
    for pid in pids:
        try:
            return _follow(pid, parts, fcs, aileron_prop, defaults)
        except NotTranslated as e:
            reasons.append("<pid> '%s': %s" % (pid.name, e))
    raise NotTranslated("; ".join(reasons))


def _gain(pid, tag, parts, fcs, defaults):
    """(value, JSBSim text) of the PID's kp, ki or kd: a number or a property with an initial
    value that no component writes."""
    element = pid.element.find(tag)
    if element is None or not (element.text or "").strip():
        return 0.0, "JSBSim: no <%s> (0)" % tag
    text = element.text.strip()
    value = number(text)
    if value is not None:
        return value, "JSBSim <%s> %s" % (tag, text)
    sign, prop = signed(text)
    writers = [p.name for p in parts if prop in p.outputs] + \
        ([fcs.producer[prop].name] if prop in fcs.producer else [])
    if writers:
        raise NotTranslated("its %s %s is written by '%s', not a constant" % (tag, prop, writers[0]))
    if prop not in defaults:
        raise NotTranslated("its %s is property %s, which has no <property value=...> default"
                            % (tag, prop))
    return sign * defaults[prop], "JSBSim %s" % text


def _follow(pid, parts, fcs, aileron_prop, defaults):
    e = pid.element
    if e.get("type") == "standard":
        raise NotTranslated('type="standard" (Kp multiplying ki and kd) is not translated')
    if e.find("clipto") is not None:
        raise NotTranslated("its <clipto> is not translated (fedsim clips only the summed command)")
    input_sign = signed(pid.inputs[0])[0]
    pvdot = (e.findtext("pvdot") or "").strip()
    if pvdot and (pvdot != EULER_BANK_RATE or input_sign < 0):
        raise NotTranslated("its <pvdot> %s is not the bank's Euler rate" % pvdot)
    gains = {tag: _gain(pid, tag, parts, fcs, defaults) for tag in ("kp", "ki", "kd")}
    ki = e.find("ki")
    rule = ki.get("type") if ki is not None else None

    # The switches from the PID to a property the FCS's aileron chain reads.
    chain = fcs.upstream(aileron_prop)
    names, sign, path, engage, wow = set(pid.outputs), input_sign, [], set(), []
    while True:
        readers = [c for c in chain if any(signed(i)[1] in names for i in c.inputs)]
        if readers:
            break
        consumers = []
        for p in parts:
            if p is pid or p in path:
                continue
            if p.type == "switch":
                tests = [t for t in p.element.findall("test")
                         if t.get("value") and signed(t.get("value"))[1] in names]
                if tests:
                    consumers.append((p, tests))
            elif p.reads(names):
                consumers.append((p, None))
        last = (path[-1] if path else pid).name
        if not consumers:
            raise NotTranslated("'%s' reaches no input of the FCS's aileron chain (%s)" %
                                (last, aileron_prop))
        if len(consumers) > 1:
            raise NotTranslated("'%s' feeds several components (%s)" %
                                (last, ", ".join("'%s'" % p.name for p, _ in consumers)))
        p, tests = consumers[0]
        if tests is None:
            raise NotTranslated("its path passes <%s> '%s' (only switches are followed)" %
                                (p.type, p.name))
        if len(tests) > 1:
            raise NotTranslated("switch '%s' passes '%s' in several tests" % (p.name, last))
        extra = [c.tag for c in p.element if c.tag not in SWITCH_PARTS]
        default_element = p.element.find("default")  # none: JSBSim's default output is 0
        default = number(default_element.get("value")) if default_element is not None else 0.0
        if extra or default != 0.0:
            raise NotTranslated("switch '%s' has %s" % (
                p.name, ", ".join("<%s>" % t for t in extra) if extra else "a default other than 0"))
        try:
            for prop, value in conditions(tests[0]):
                if WOW.match(prop) and value == 0.0:
                    wow.append((p.name, prop))
                elif value == 1.0 and not WOW.match(prop):
                    engage.add(prop)
                else:
                    raise NotTranslated("tests %s == %g" % (prop, value))
        except NotTranslated as err:
            raise NotTranslated("switch '%s' %s" % (p.name, err))
        sign *= signed(tests[0].get("value"))[0]
        path.append(p)
        names = set(p.outputs)
    if not path or len(engage) != 1:
        raise NotTranslated("its switches test %s, not one engage property (P == 1)" %
                            (", ".join(sorted(engage)) or "no engage property"))
    (engage,) = engage
    summer = readers[0]
    fed = [signed(i) for i in summer.inputs if signed(i)[1] in names]
    pilot = [signed(i)[0] for i in summer.inputs if signed(i)[1] == PILOT_AILERON]
    if len(readers) > 1 or summer.type != "summer" or len(fed) != 1 or len(pilot) != 1:
        raise NotTranslated("'%s' is read by FCS %s '%s', not summed once with the pilot's %s" %
                            (path[-1].name, summer.type, summer.name, PILOT_AILERON))
    sign *= fed[0][0] * pilot[0]

    trigger_name = (e.findtext("trigger") or "").strip()
    trigger = next((p for p in parts if trigger_name and trigger_name in p.outputs), None)
    resets_when_off = trigger is not None and _resets_unless(trigger, engage)
    return WingLeveller(
        pid=pid, gains=gains, negated=sign > 0,
        integration=rule if rule in INTEGRATION_RULES else "ab2", integration_default=rule is None,
        rate_from=pvdot or None, switches=path, engage=engage,
        engaged_at_start=defaults.get(engage, 0.0) == 1.0, wow=wow,
        fcs_input=fed[0][1], summer=summer, trigger_name=trigger_name or None,
        trigger=trigger if resets_when_off else None)


def _resets_unless(switch, engage):
    """True when `switch` (a PID trigger) is negative (reset) by default and 0 (integrate)
    when, and only when, `engage` == 1: JSBSim's idiom for an integral reset while off."""
    if switch.type != "switch":
        return False
    default = switch.element.find("default")
    tests = switch.element.findall("test")
    if default is None or (number(default.get("value")) or 0.0) >= 0.0 or len(tests) != 1:
        return False
    try:
        return number(tests[0].get("value")) == 0.0 and conditions(tests[0]) == [(engage, 1.0)]
    except NotTranslated:
        return False
