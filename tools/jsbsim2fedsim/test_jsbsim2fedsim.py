#!/usr/bin/env python3
"""Tests of jsbsim2fedsim on a small synthetic JSBSim aircraft (no JSBSim tree needed).

Run: python3 -m unittest discover -s tools/jsbsim2fedsim -p 'test_*.py'
"""

import contextlib
import io
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import calibration  # noqa: E402
import jsbsim2fedsim  # noqa: E402
import jsbsim_aero  # noqa: E402
import jsbsim_xml as jx  # noqa: E402

AIRCRAFT = """<?xml version="1.0"?>
<fdm_config name="testplane">
  <fileheader><description> A made-up test aeroplane. </description></fileheader>
  <metrics>
    <wingarea unit="FT2"> 100.0 </wingarea>
    <wingspan unit="FT"> 20.0 </wingspan>
    <chord unit="FT"> 5.0 </chord>
    <location name="AERORP" unit="IN"> <x> 40 </x> <y> 0 </y> <z> 10 </z> </location>
    <location name="EYEPOINT" unit="IN"> <x> 20 </x> <y> -10 </y> <z> 30 </z> </location>
  </metrics>
  <mass_balance>
    <ixx unit="SLUG*FT2"> 1000 </ixx> <iyy unit="SLUG*FT2"> 2000 </iyy>
    <izz unit="SLUG*FT2"> 2800 </izz> <ixz unit="SLUG*FT2"> 50 </ixz>
    <emptywt unit="LBS"> 2000 </emptywt>
    <location name="CG" unit="IN"> <x> 42 </x> <y> 0 </y> <z> 12 </z> </location>
    <pointmass name="PILOT"> <weight unit="KG"> 80 </weight>
      <location unit="M"> <x> 1.0 </x> <y> 0 </y> <z> 0.5 </z> </location> </pointmass>
  </mass_balance>
  <ground_reactions>
    <contact type="BOGEY" name="NOSE">
      <location unit="IN"> <x> -10 </x> <y> 0 </y> <z> -30 </z> </location>
      <static_friction> 0.8 </static_friction> <dynamic_friction> 0.5 </dynamic_friction>
      <rolling_friction> 0.02 </rolling_friction>
      <strut_force><function><sum>
        <product><value> -1000 </value><property> gear/unit[0]/compression-ft </property></product>
        <ifthen><ge><property> gear/unit[0]/compression-velocity-fps </property><value> 0 </value></ge>
          <product><value> -100 </value><property> gear/unit[0]/compression-velocity-fps </property></product>
          <product><value> -300 </value><property> gear/unit[0]/compression-velocity-fps </property></product>
        </ifthen>
      </sum></function></strut_force>
      <max_steer unit="DEG"> 20 </max_steer> <brake_group> NOSE </brake_group>
    </contact>
  </ground_reactions>
  <propulsion>
    <tank type="FUEL"> <location unit="IN"> <x> 45 </x> <y> -50 </y> <z> 20 </z> </location>
      <capacity unit="LBS"> 100 </capacity> <contents unit="LBS"> 50 </contents> </tank>
  </propulsion>
  <flight_control name="test">
    <channel name="Pitch">
      <summer name="fcs/pitch-sum"> <input> fcs/elevator-cmd-norm </input>
        <input> ap/elevator_cmd </input> <clipto> <min> -1 </min> <max> 1 </max> </clipto> </summer>
      <aerosurface_scale name="fcs/elevator-scale"> <input> fcs/pitch-sum </input>
        <range> <min> -0.4 </min> <max> 0.3 </max> </range> </aerosurface_scale>
      <actuator name="fcs/elevator-actuator"> <input> fcs/elevator-scale </input>
        <lag> 20 </lag> <rate_limit> 2.0 </rate_limit>
        <clipto> <min> -0.35 </min> <max> 0.35 </max> </clipto>
        <output> fcs/elevator-pos-rad </output> </actuator>
    </channel>
    <channel name="Yaw">
      <aerosurface_scale name="Rudder Control"> <input> fcs/rudder-cmd-norm </input>
        <range> <min> -20 </min> <max> 20 </max> </range> <gain> 0.0174533 </gain>
        <output> fcs/rudder-pos-rad </output> </aerosurface_scale>
    </channel>
    <channel name="Flaps">
      <kinematic name="fcs/flap-control"> <input> fcs/flap-cmd-norm </input>
        <traverse> <setting> <position> 0 </position> <time> 0 </time> </setting>
          <setting> <position> 40 </position> <time> 8 </time> </setting> </traverse>
        <output> fcs/flap-pos-deg </output> </kinematic>
    </channel>
  </flight_control>
  <aerodynamics>
    <hysteresis_limits unit="DEG"> <min> 5 </min> <max> 20 </max> </hysteresis_limits>
    <function name="aero/function/ge">
      <table> <independentVar> aero/h_b-mac-ft </independentVar>
        <tableData> 0.0 1.2
                    1.0 1.0 </tableData> </table>
    </function>
    <axis name="LIFT">
      <function name="aero/coefficient/CLa">
        <product> <property> aero/qbar-area </property> <property> aero/function/ge </property>
          <table> <independentVar lookup="row"> aero/alpha-deg </independentVar>
            <independentVar lookup="column"> fcs/flap-pos-deg </independentVar>
            <tableData>       0.0   40.0
                      -10.0  -0.5   0.0
                       10.0   1.0   1.5 </tableData> </table> </product>
      </function>
    </axis>
    <axis name="DRAG">
      <function name="aero/coefficient/CD0">
        <product> <property> aero/qbar-psf </property> <property> metrics/Sw-sqft </property>
          <value> 0.03 </value> </product> </function>
      <function name="aero/coefficient/CDsum">
        <sum> <value> 1 </value> <value> 2 </value> </sum> </function>
    </axis>
    <axis name="PITCH">
      <function name="aero/coefficient/Cmq">
        <product> <property> aero/qbar-area </property> <property> metrics/cbarw-ft </property>
          <property> aero/ci2vel </property> <property> velocities/q-aero-rad_sec </property>
          <value> -10 </value> </product> </function>
      <function name="aero/coefficient/Cmde">
        <product> <property> aero/qbar-area </property> <property> metrics/cbarw-ft </property>
          <property> fcs/elevator-pos-deg </property> <value> -0.02 </value> </product> </function>
      <function name="aero/coefficient/Cm_missing_c">
        <product> <property> aero/qbar-area </property> <value> 0.1 </value> </product> </function>
    </axis>
    <axis name="YAW">
      <function name="aero/coefficient/Cndr">
        <product> <property> aero/qbar-area </property> <property> metrics/bw-ft </property>
          <property> fcs/rudder-pos-rad </property> <value> -0.1 </value> </product> </function>
    </axis>
  </aerodynamics>
</fdm_config>
"""


# The test aircraft's rudder with the JSBSim 737's yaw-damper chain: a Mach-scheduled gain on
# the air-relative yaw rate summed into the rudder command.
YAW_DAMPER_RUDDER = """    <channel name="Yaw">
      <scheduled_gain name="Yaw Damper"> <input> velocities/r-aero-rad_sec </input>
        <table> <independentVar> velocities/mach </independentVar>
          <tableData> 0.0 0.0
                      0.2 2.0 </tableData> </table> </scheduled_gain>
      <summer name="Rudder Sum"> <input> fcs/rudder-cmd-norm </input> <input> fcs/yaw-damper </input>
        <clipto> <min> -1 </min> <max> 1 </max> </clipto> </summer>
      <aerosurface_scale name="Rudder Control"> <input> fcs/rudder-sum </input>
        <range> <min> -20 </min> <max> 20 </max> </range> <gain> 0.0174533 </gain>
        <output> fcs/rudder-pos-rad </output> </aerosurface_scale>
    </channel>"""
PLAIN_RUDDER = AIRCRAFT[AIRCRAFT.index('    <channel name="Yaw">'):AIRCRAFT.index('    <channel name="Flaps">')].rstrip("\n")


def convert(aircraft=None, pitch_trim=None, files=None):
    """Sections, notes and sign checks of `aircraft`, with `files` (name -> text) beside it."""
    aircraft = AIRCRAFT if aircraft is None else aircraft
    notes = []
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "testplane.xml")
        for name, text in dict(files or {}, **{"testplane.xml": aircraft}).items():
            with open(os.path.join(d, name), "w") as f:
                f.write(text)
        conv = jsbsim2fedsim.Converter(path, d, notes, pitch_trim)
        sections = {"geometry": conv.geometry(), "mass": conv.mass(),
                    "flight_controls": conv.flight_controls(), "aerodynamics": conv.aerodynamics(),
                    "landing_gear": conv.landing_gear(), "limits": conv.limits()}
        checks = conv.control_sign_report()
    return sections, notes, checks


def plain(v):
    """Strip Commented wrappers."""
    if isinstance(v, jsbsim2fedsim.Commented):
        return plain(v.value)
    if isinstance(v, dict):
        return {k: plain(x) for k, x in v.items()}
    if isinstance(v, list):
        return [plain(x) for x in v]
    return v


class ConverterTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        sections, cls.notes, cls.checks = convert()
        cls.s = plain(sections)

    def test_geometry_units_and_frame(self):
        g = self.s["geometry"]
        self.assertAlmostEqual(g["wing_area_m2"], 100 * 0.3048 ** 2, places=12)
        self.assertEqual(g["aero_reference_point_m"], [-40 * 0.0254, 0.0, -10 * 0.0254])
        self.assertEqual(g["pilot_eye_point_m"], [-20 * 0.0254, -10 * 0.0254, -30 * 0.0254])

    def test_mass_and_inertia_signs(self):
        m = self.s["mass"]
        self.assertAlmostEqual(m["empty_mass_kg"], 2000 * 0.45359237, places=9)
        slug_ft2 = jx.SLUG * 0.3048 ** 2
        self.assertAlmostEqual(m["empty_inertia"]["ixz_kgm2"], -50 * slug_ft2, places=9)
        self.assertEqual(m["point_masses"][0]["position_m"], [-1.0, 0.0, -0.5])
        self.assertEqual(m["point_masses"][0]["mass_kg"], 80.0)
        tank = m["fuel_tanks"][0]
        self.assertEqual(tank["name"], "tank 0 left")
        self.assertAlmostEqual(tank["initial_kg"], 50 * 0.45359237, places=12)

    def test_elevator_travel_clip_lag_and_rate(self):
        e = self.s["flight_controls"]["elevator"]
        self.assertAlmostEqual(e["deflection_at_plus_one_deg"], math.degrees(0.3), places=9)
        self.assertAlmostEqual(e["deflection_at_minus_one_deg"], math.degrees(-0.4), places=9)
        self.assertAlmostEqual(e["min_deflection_deg"], math.degrees(-0.35), places=9)
        self.assertNotIn("max_deflection_deg", e)  # 0.3 rad never reaches the 0.35 clip
        self.assertAlmostEqual(e["time_constant_s"], 1 / 20.0, places=12)
        self.assertAlmostEqual(e["rate_limit_deg_per_s"], math.degrees(2.0), places=9)
        self.assertTrue(any("ap/elevator_cmd" in n for n in self.notes))

    def test_rudder_command_sign_is_flipped(self):
        r = self.s["flight_controls"]["rudder"]
        self.assertAlmostEqual(r["deflection_at_plus_one_deg"], -20 * 0.0174533 * 180 / math.pi, places=6)
        self.assertIn("rudder command +1 -> Cn change +", self.checks[-1])

    def test_flaps_from_the_kinematic(self):
        f = self.s["flight_controls"]["flaps"]
        self.assertEqual(f["positions_norm"], [0.0, 1.0])
        self.assertEqual(f["transit_times_s"], [8.0])
        self.assertEqual(f["full_travel_deg"], 40.0)

    def test_table_in_degrees_becomes_radians_and_factor_is_named(self):
        a = self.s["aerodynamics"]
        self.assertEqual(a["factors"][0]["name"], "ge")
        self.assertEqual(a["factors"][0]["table"]["row"], "h_over_b")
        term = a["lift"][0]
        self.assertEqual(term["table"]["row"], "alpha_rad")
        self.assertEqual(term["table"]["column"], "flap_deg")
        self.assertAlmostEqual(term["table"]["row_breakpoints"][1], math.radians(10), places=12)
        self.assertEqual(term["multiply_by"], ["ge"])
        self.assertAlmostEqual(a["stall_hysteresis"]["alpha_set_rad"], math.radians(20), places=12)

    def test_rates_pair_and_degree_multipliers_fold(self):
        pitch = {t["name"]: t for t in self.s["aerodynamics"]["pitch_moment"]}
        self.assertEqual(pitch["Cmq"], {"name": "Cmq", "value": -10.0, "multiply_by": ["q_hat"]})
        self.assertAlmostEqual(pitch["Cmde"]["value"], -0.02 * 180 / math.pi, places=12)
        self.assertEqual(pitch["Cmde"]["multiply_by"], ["elevator_rad"])

    def test_untranslatable_terms_are_reported_and_dropped(self):
        names = [t["name"] for t in self.s["aerodynamics"]["drag"]]
        self.assertEqual(names, ["CD0"])  # q * S recognised; the <sum> term dropped
        self.assertTrue(any("CDsum" in n and "<sum>" in n for n in self.notes))
        self.assertNotIn("Cm_missing_c", [t["name"] for t in self.s["aerodynamics"]["pitch_moment"]])
        self.assertTrue(any("Cm_missing_c" in n and "expected q*S*c" in n for n in self.notes))

    def test_strut_function_is_read_as_spring_and_dampers(self):
        nose = self.s["landing_gear"]["contacts"][0]
        lbf_ft = jx.LBF / 0.3048
        self.assertAlmostEqual(nose["spring_n_per_m"], 1000 * lbf_ft, places=6)
        self.assertAlmostEqual(nose["damping_n_s_per_m"], 100 * lbf_ft, places=6)
        self.assertAlmostEqual(nose["rebound_damping_n_s_per_m"], 300 * lbf_ft, places=6)
        self.assertAlmostEqual(nose["max_steer_deg"], 20.0, places=9)
        self.assertNotIn("brake_group", nose)  # NOSE brakes are not modelled
        self.assertTrue(any("NOSE" in n for n in self.notes))

    def test_interpolation_clamps_like_fedsim(self):
        self.assertEqual(jx.interpolate([[0.0, 1.0]], [2.0, 4.0], [5.0]), 4.0)
        self.assertEqual(jx.interpolate([[0.0, 1.0]], [2.0, 4.0], [0.25]), 2.5)
        term = {"value": 2.0, "multiply_by": ["alpha_rad"]}
        self.assertEqual(jsbsim_aero.evaluate_term(term, {"alpha_rad": 0.5}), 1.0)


# A single piston engine with a fixed-pitch propeller that states JSBSim's <cp_factor> (and no
# <ct_factor>), for the propulsion translation and the calibration overlay.
PISTON_AIRCRAFT = AIRCRAFT.replace("""  <propulsion>
""", """  <propulsion>
    <engine file="testengine"> <feed> 0 </feed>
      <thruster file="testprop">
        <location unit="IN"> <x> -30 </x> <y> 0 </y> <z> 20 </z> </location>
        <orient unit="DEG"> <roll> 0 </roll> <pitch> 0 </pitch> <yaw> 0 </yaw> </orient>
        <sense> 1 </sense>
      </thruster>
    </engine>
""")
ENGINE = """<?xml version="1.0"?>
<piston_engine name="test">
  <minmp unit="INHG"> 10 </minmp> <maxmp unit="INHG"> 28 </maxmp>
  <displacement unit="IN3"> 300 </displacement> <maxhp> 150 </maxhp> <bsfc> 0.45 </bsfc>
  <cycles> 4 </cycles> <idlerpm> 600 </idlerpm> <maxrpm> 2700 </maxrpm>
</piston_engine>
"""
PROPELLER = """<?xml version="1.0"?>
<propeller name="test">
  <ixx> 1.5 </ixx> <diameter unit="IN"> 72 </diameter> <numblades> 2 </numblades>
  <minpitch> 20 </minpitch> <maxpitch> 20 </maxpitch>
  <cp_factor> 1.25 </cp_factor>
  <table name="C_THRUST" type="internal"> <tableData>
    0.0 0.07
    1.0 0.02 </tableData> </table>
  <table name="C_POWER" type="internal"> <tableData>
    0.0 0.06
    1.0 0.03 </tableData> </table>
</propeller>
"""
OVERLAY = """# a comment line
fedsim_pack_calibration: 1
pack: testplane.yaml
procedure: "made up for the test"   # trailing comment
engines:
  engine:
    propeller:
      thrust_coefficient_factor:
        value: 1.05
        source: "POH: ground roll 900 ft"
      power_coefficient_factor:
        value: 0.9   # replaces the JSBSim factor
        source: plain text is fine too
"""

# A fade band appended to OVERLAY's propeller section (lines 14-19).
FADE = """      factor_fade_start_advance_ratio:
        value: 0.35
        source: "end of the take-off roll"
      factor_fade_end_advance_ratio:
        value: 0.55
        source: "below the cruise"
"""


class PropellerAndCalibrationTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        d = self.dir.name
        for name, text in (("testplane.xml", PISTON_AIRCRAFT), ("testengine.xml", ENGINE),
                           ("testprop.xml", PROPELLER), ("testplane.calibration.yaml", OVERLAY)):
            with open(os.path.join(d, name), "w") as f:
                f.write(text)
        self.aircraft = os.path.join(d, "testplane.xml")
        self.overlay = os.path.join(d, "testplane.calibration.yaml")

    def tearDown(self):
        self.dir.cleanup()

    def write_overlay(self, text):
        with open(self.overlay, "w") as f:
            f.write(text)

    def expect_error(self, text, line, field, words):
        self.write_overlay(text)
        with self.assertRaises(calibration.CalibrationError) as caught:
            overlay = calibration.read_overlay(self.overlay, "testplane.yaml")
            sections, notes = self.sections()
            calibration.apply(overlay, sections, notes, jsbsim2fedsim.Commented)
        message = str(caught.exception)
        self.assertTrue(message.startswith("%s:%d: %s" % (self.overlay, line, field)), message)
        self.assertIn(words, message)

    def sections(self):
        notes = []
        conv = jsbsim2fedsim.Converter(self.aircraft, self.dir.name, notes)
        return {"propulsion": conv.propulsion()}, notes

    def test_jsbsim_cp_factor_is_translated(self):
        sections, notes = self.sections()
        prop = plain(sections["propulsion"]["engines"][0]["propeller"])
        self.assertEqual(prop["power_coefficient_factor"], 1.25)
        self.assertNotIn("thrust_coefficient_factor", prop)  # JSBSim's default 1
        self.assertFalse(any("cp_factor" in n for n in notes))  # translated, not dropped
        self.assertEqual(list(prop).index("power_coefficient_factor"),
                         list(prop).index("power_coefficient") + 1)

    def test_overlay_values_replace_and_follow_the_tables_with_their_sources_noted(self):
        overlay = calibration.read_overlay(self.overlay, "testplane.yaml")
        self.assertEqual(overlay["procedure"], "made up for the test")
        sections, notes = self.sections()
        calibration.apply(overlay, sections, notes, jsbsim2fedsim.Commented)
        raw = sections["propulsion"]["engines"][0]["propeller"]
        self.assertEqual(raw["thrust_coefficient_factor"].comment,
                         "calibrated: testplane.calibration.yaml")
        prop = plain(raw)
        self.assertEqual(prop["thrust_coefficient_factor"], 1.05)
        self.assertEqual(prop["power_coefficient_factor"], 0.9)
        keys = list(prop)
        self.assertEqual(keys[keys.index("power_coefficient") + 1:keys.index("power_coefficient") + 3],
                         ["power_coefficient_factor", "thrust_coefficient_factor"])
        self.assertTrue(any("thrust_coefficient_factor = 1.05" in n and "ground roll 900 ft" in n
                            for n in notes))
        self.assertTrue(any("power_coefficient_factor = 0.9" in n and "replaces JSBSim's "
                            "<cp_factor> 1.25" in n for n in notes))
        self.assertTrue(any("made up for the test" in n for n in notes))

    def test_converter_merges_the_overlay_into_the_written_pack(self):
        out = os.path.join(self.dir.name, "testplane.yaml")
        status = jsbsim2fedsim.main([self.aircraft, "--engine-dir", self.dir.name, "-o", out,
                                     "--calibration", self.overlay])
        self.assertEqual(status, 0)
        with open(out) as f:
            text = f.read()
        self.assertIn("thrust_coefficient_factor: 1.05  # calibrated: testplane.calibration.yaml",
                      text)
        self.assertIn("calibrated by testplane.calibration.yaml", text)
        # Without the overlay the pack keeps JSBSim's factor only.
        self.assertEqual(jsbsim2fedsim.main([self.aircraft, "--engine-dir", self.dir.name, "-o",
                                             out]), 0)
        with open(out) as f:
            text = f.read()
        self.assertIn("power_coefficient_factor: 1.25  # JSBSim <cp_factor>", text)
        self.assertNotIn("thrust_coefficient_factor", text)

    def test_overlay_for_another_pack_is_refused(self):
        out = os.path.join(self.dir.name, "other.yaml")
        status = jsbsim2fedsim.main([self.aircraft, "--engine-dir", self.dir.name, "-o", out,
                                     "--calibration", self.overlay])
        self.assertEqual(status, 1)
        self.assertFalse(os.path.exists(out))

    def test_bad_overlays_fail_at_their_file_line_and_field(self):
        base = OVERLAY
        self.expect_error(base.replace("value: 1.05", "value: 0.0"), 9,
                          "engines.engine.propeller.thrust_coefficient_factor.value",
                          "outside the allowed range [0.1, 10]")
        self.expect_error(base.replace("value: 1.05", "value: -2"), 9,
                          "engines.engine.propeller.thrust_coefficient_factor.value",
                          "outside the allowed range")
        self.expect_error(base.replace("value: 1.05", "value: .nan"), 9,
                          "engines.engine.propeller.thrust_coefficient_factor.value",
                          "expected a finite number")
        self.expect_error(base.replace("value: 1.05", "value: 11"), 9,
                          "engines.engine.propeller.thrust_coefficient_factor.value",
                          "outside the allowed range")
        self.expect_error(base.replace("      thrust_coefficient_factor:", "      thrust_factor:"),
                          8, "engines.engine.propeller.thrust_factor", "unknown field")
        self.expect_error(base.replace("        source: \"POH: ground roll 900 ft\"\n", ""), 8,
                          "engines.engine.propeller.thrust_coefficient_factor.source", "missing")
        self.expect_error(base.replace("  engine:", "  engine 2:"), 9,
                          "engines.engine 2.propeller.thrust_coefficient_factor",
                          "no engine named 'engine 2'")
        self.expect_error(base.replace("pack: testplane.yaml", "pack: c172.yaml"), 3, "pack",
                          "belongs to c172.yaml")
        self.expect_error(base.replace("fedsim_pack_calibration: 1", "fedsim_pack_calibration: 2"),
                          2, "fedsim_pack_calibration", "unsupported format version")
        self.expect_error(base.replace("value: 1.05", "value: [1.05]"), 9,
                          "engines.engine.propeller.thrust_coefficient_factor.value",
                          "only plain scalars")
        self.expect_error(base + "  - engine\n", 14, "", "lists are not allowed")
        self.expect_error(base.replace("    propeller:", "    piston:"), 7,
                          "engines.engine.piston", "unknown field")
        self.expect_error(base + "engines:\n  x: 1\n", 14, "engines", "duplicate key")

    def test_fade_band_follows_the_factors_and_is_noted(self):
        self.write_overlay(OVERLAY + FADE)
        overlay = calibration.read_overlay(self.overlay, "testplane.yaml")
        sections, notes = self.sections()
        calibration.apply(overlay, sections, notes, jsbsim2fedsim.Commented)
        prop = plain(sections["propulsion"]["engines"][0]["propeller"])
        self.assertEqual(prop["factor_fade_start_advance_ratio"], 0.35)
        self.assertEqual(prop["factor_fade_end_advance_ratio"], 0.55)
        keys = list(prop)
        at = keys.index("thrust_coefficient_factor")
        self.assertEqual(keys[at + 1:at + 3], ["factor_fade_start_advance_ratio",
                                               "factor_fade_end_advance_ratio"])
        self.assertTrue(any("factor_fade_end_advance_ratio = 0.55" in n and "cruise" in n
                            for n in notes))

    def test_bad_fade_bands_fail_at_their_file_line_and_field(self):
        field = "engines.engine.propeller."
        # Lines: OVERLAY has 13, FADE starts on line 14 (start) and 17 (end), values 15 and 18.
        self.expect_error(OVERLAY + FADE.replace("value: 0.55", "value: 0.35"), 18,
                          field + "factor_fade_end_advance_ratio.value",
                          "must exceed factor_fade_start_advance_ratio (0.35)")
        self.expect_error(OVERLAY + FADE.replace("value: 0.55", "value: 0.2"), 18,
                          field + "factor_fade_end_advance_ratio.value", "must exceed")
        self.expect_error(OVERLAY + FADE.replace("value: 0.55", "value: 4"), 18,
                          field + "factor_fade_end_advance_ratio.value",
                          "outside the allowed range [0, 3]")
        self.expect_error(OVERLAY + FADE.replace("value: 0.35", "value: -0.1"), 15,
                          field + "factor_fade_start_advance_ratio.value",
                          "outside the allowed range [0, 3]")
        self.expect_error(OVERLAY + FADE.replace("value: 0.35", "value: .inf"), 15,
                          field + "factor_fade_start_advance_ratio.value",
                          "expected a finite number")
        only_start = "\n".join(FADE.splitlines()[:3]) + "\n"
        self.expect_error(OVERLAY + only_start, 14, field + "factor_fade_start_advance_ratio",
                          "needs factor_fade_end_advance_ratio too")
        only_end = "\n".join(FADE.splitlines()[3:]) + "\n"
        self.expect_error(OVERLAY + only_end, 14, field + "factor_fade_end_advance_ratio",
                          "needs factor_fade_start_advance_ratio too")

    def test_shipped_c172_overlay_reads(self):
        path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data",
                            "aircraft", "c172.calibration.yaml")
        overlay = calibration.read_overlay(path, "c172.yaml")
        keys = sorted(s["key"] for s in overlay["settings"])
        self.assertEqual(keys, ["factor_fade_end_advance_ratio", "factor_fade_start_advance_ratio",
                                "power_coefficient_factor", "thrust_coefficient_factor"])
        for s in overlay["settings"]:
            # The factors are identified from the handbook; the band is a stated choice.
            self.assertIn("stated choice" if s["key"].startswith("factor_fade")
                          else "Pilot's Operating Handbook", s["source"])


# The test aircraft with the c172x's roll channel (the autopilot's ap/aileron_cmd summed with the
# pilot's aileron command) and a roll term on the aileron, and the c172ap's wing leveller as an
# <autopilot> file beside it.
ROLL_CHANNEL = """    <channel name="Roll">
      <summer name="fcs/roll-trim-sum"> <input> ap/aileron_cmd </input>
        <input> fcs/aileron-cmd-norm </input> <input> fcs/roll-trim-cmd-norm </input>
        <clipto> <min> -1 </min> <max> 1 </max> </clipto> </summer>
      <aerosurface_scale name="fcs/aileron-control"> <input> fcs/roll-trim-sum </input>
        <range> <min> -0.3 </min> <max> 0.3 </max> </range>
        <output> fcs/aileron-pos-rad </output> </aerosurface_scale>
    </channel>
"""
ROLL_AIRCRAFT = AIRCRAFT.replace('    <channel name="Flaps">', ROLL_CHANNEL + '    <channel name="Flaps">').replace(
    '    <axis name="YAW">', """    <axis name="ROLL">
      <function name="aero/coefficient/Clda">
        <product> <property> aero/qbar-area </property> <property> metrics/bw-ft </property>
          <property> fcs/aileron-pos-rad </property> <value> 0.2 </value> </product> </function>
    </axis>
    <axis name="YAW">""").replace("</flight_control>", """</flight_control>
  <autopilot file="testap"/>""")
AUTOPILOT = """<?xml version="1.0"?>
<autopilot name="Test Autopilot">
  <property> ap/attitude_hold </property>
  <property value="50.0"> ap/roll-pid-kp </property>
  <property value="5.0"> ap/roll-pid-ki </property>
  <property value="17.0"> ap/roll-pid-kd </property>
  <channel name="Roll wing leveler">
    <sensor name="fcs/attitude/sensor/phi-rad"> <input> attitude/phi-rad </input>
      <lag> 0.5 </lag> <bias> 0.001 </bias> </sensor>
    <switch name="fcs/wing-leveler-ap-on-off"> <default value="-1"/>
      <test value="0"> ap/attitude_hold == 1 </test> </switch>
    <pid name="fcs/roll-ap-error-pid"> <input>attitude/phi-rad</input>
      <kp> ap/roll-pid-kp </kp> <ki> ap/roll-pid-ki </ki> <kd> ap/roll-pid-kd </kd>
      <trigger> fcs/wing-leveler-ap-on-off </trigger> </pid>
    <switch name="fcs/roll-ap-autoswitch"> <default value="0.0"/>
      <test value="-fcs/roll-ap-error-pid"> ap/attitude_hold == 1 </test> </switch>
  </channel>
  <channel name="Roll heading hold">
    <pid name="fcs/heading-pi-controller"> <input> ap/heading-error </input>
      <kp> 6.0 </kp> <ki> 0.13 </ki> </pid>
    <switch name="fcs/roll-command-selector"> <default value="0.0"/>
      <test value="fcs/heading-pi-controller">
        ap/heading_hold == 1
        gear/unit[2]/WOW == 0
      </test>
      <test value="fcs/roll-ap-autoswitch">
        ap/attitude_hold == 1
        gear/unit[2]/WOW == 0
      </test>
      <output>ap/aileron_cmd</output>
    </switch>
  </channel>
  <channel name="Pitch altitude hold">
    <pure_gain name="fcs/elevator"> <input> ap/altitude-error </input> <gain> -1.0 </gain>
      <output> ap/elevator_cmd </output> </pure_gain>
  </channel>
</autopilot>
"""


class FlightControlSystemTest(unittest.TestCase):
    def test_yaw_damper_chain_becomes_the_pack_yaw_damper(self):
        sections, notes, _ = convert(AIRCRAFT.replace(PLAIN_RUDDER, YAW_DAMPER_RUDDER))
        fc = plain(sections)["flight_controls"]
        yd = fc["yaw_damper"]["gain_per_radps"]
        self.assertEqual(yd["row"], "mach")
        self.assertEqual(yd["row_breakpoints"], [0.0, 0.2])
        # JSBSim rudder +2 per rad/s of yaw rate is fedsim rudder -2 (the rudder command's sign
        # is flipped): a yaw rate to the right gives left rudder, it damps.
        self.assertAlmostEqual(yd["values"][0], 0.0, places=9)
        self.assertAlmostEqual(yd["values"][1], -2.0, places=6)
        self.assertTrue(fc["yaw_damper"]["engaged_at_start"])
        self.assertFalse(any("not translated" in n and "Yaw Damper" in n for n in notes), notes)
        self.assertTrue(any("translated as flight_controls.yaw_damper" in n for n in notes))
        # The travel is unchanged by the damper.
        self.assertAlmostEqual(fc["rudder"]["deflection_at_plus_one_deg"], -20 * 0.0174533 * 180 / math.pi, places=6)

    def test_a_filter_on_the_damper_path_is_not_translated(self):
        filtered = YAW_DAMPER_RUDDER.replace(
            '<summer name="Rudder Sum">',
            '<lag_filter name="YD Filter"> <input> fcs/yaw-damper </input> <c1> 2 </c1> </lag_filter>\n'
            '      <summer name="Rudder Sum">').replace(
            "<input> fcs/yaw-damper </input>\n        <clipto>", "<input> fcs/yd-filter </input>\n        <clipto>")
        sections, notes, _ = convert(AIRCRAFT.replace(PLAIN_RUDDER, filtered))
        self.assertNotIn("yaw_damper", plain(sections)["flight_controls"])
        self.assertTrue(any("yaw damper path holds <lag_filter>" in n for n in notes), notes)

    def test_no_damper_without_a_yaw_rate_input(self):
        sections, _, _ = convert()
        self.assertNotIn("yaw_damper", plain(sections)["flight_controls"])
        self.assertNotIn("pitch_trim", plain(sections)["flight_controls"])

    def wing_leveller(self, autopilot=AUTOPILOT, aircraft=ROLL_AIRCRAFT):
        sections, notes, _ = convert(aircraft, files={"testap.xml": autopilot})
        return plain(sections)["flight_controls"].get("wing_leveller"), notes

    def test_wing_leveller_chain_becomes_the_pack_wing_leveller(self):
        wl, notes = self.wing_leveller()
        # JSBSim's switch passes -PID: the aileron gets -(Kp phi + Ki integral + Kd dphi/dt),
        # the pack's formula, with the gains the properties start at.
        self.assertEqual(wl, {"bank_gain_per_rad": 50.0, "bank_integral_gain_per_rad_s": 5.0,
                              "bank_rate_gain_per_radps": 17.0, "airborne_only": True,
                              "engaged_at_start": False})
        translated = [n for n in notes if "translated as flight_controls.wing_leveller" in n]
        self.assertEqual(len(translated), 1, notes)
        self.assertIn("fedsim's for JSBSim's ap/attitude_hold", translated[0])
        self.assertIn("not translated: channels 'Roll heading hold' (all but "
                      "'fcs/roll-command-selector', on the wing leveller's path), "
                      "'Pitch altitude hold'", translated[0])
        self.assertTrue(any("sensor 'fcs/attitude/sensor/phi-rad' (lag, bias) is not on the wing "
                            "leveller's path" in n for n in notes), notes)
        self.assertTrue(any("no anti-windup" in n and "backward difference" in n for n in notes))
        # The autopilot's output is carried now; the pack gains no other note on the aileron.
        self.assertFalse(any("input ap/aileron_cmd" in n for n in notes), notes)
        self.assertFalse(any("<autopilot> 'testap' is not translated" in n for n in notes))
        self.assertFalse(any("negated" in n for n in notes))

    def test_written_pack_names_the_autopilot_file_and_the_jsbsim_figures(self):
        with tempfile.TemporaryDirectory() as d:
            for name, text in (("testplane.xml", ROLL_AIRCRAFT), ("testap.xml", AUTOPILOT)):
                with open(os.path.join(d, name), "w") as f:
                    f.write(text)
            out = os.path.join(d, "testplane.yaml")
            with contextlib.redirect_stderr(io.StringIO()):
                self.assertEqual(jsbsim2fedsim.main([os.path.join(d, "testplane.xml"), "-o", out,
                                                     "--engine-dir", d]), 0)
            with open(out) as f:
                text = f.read()
        self.assertIn("# from JSBSim testplane.xml, testap.xml", text)
        self.assertIn("""  wing_leveller:
    bank_gain_per_rad: 50.0  # JSBSim ap/roll-pid-kp (testap.xml 'fcs/roll-ap-error-pid')
    bank_integral_gain_per_rad_s: 5.0  # JSBSim ap/roll-pid-ki
    bank_rate_gain_per_radps: 17.0  # JSBSim ap/roll-pid-kd
    airborne_only: true  # 'fcs/roll-command-selector' tests gear/unit[2]/WOW == 0
    engaged_at_start: false  # JSBSim ap/attitude_hold starts at 0
""", text)

    def test_a_switch_passing_plus_pid_gives_negated_gains(self):
        wl, notes = self.wing_leveller(AUTOPILOT.replace('value="-fcs/roll-ap-error-pid"',
                                                         'value="fcs/roll-ap-error-pid"'))
        self.assertEqual((wl["bank_gain_per_rad"], wl["bank_integral_gain_per_rad_s"],
                          wl["bank_rate_gain_per_radps"]), (-50.0, -5.0, -17.0))
        self.assertTrue(any("passes +'fcs/roll-ap-error-pid'" in n and "negated" in n
                            for n in notes), notes)

    def test_inline_autopilot_with_numeric_gains_and_no_gear_test(self):
        ap = AUTOPILOT.replace('<?xml version="1.0"?>\n', "").replace("<kd> ap/roll-pid-kd </kd>", "<kd> 2.5 </kd>").replace(
            "<ki> ap/roll-pid-ki </ki>", "").replace(
            "        ap/attitude_hold == 1\n        gear/unit[2]/WOW == 0", "        ap/attitude_hold == 1")
        wl, notes = self.wing_leveller(aircraft=ROLL_AIRCRAFT.replace('<autopilot file="testap"/>', ap))
        self.assertEqual((wl["bank_gain_per_rad"], wl["bank_integral_gain_per_rad_s"],
                          wl["bank_rate_gain_per_radps"], wl["airborne_only"]), (50.0, 0.0, 2.5, False))
        self.assertTrue(any(n.startswith("JSBSim <autopilot> 'Test Autopilot': its wing leveller")
                            for n in notes), notes)
        # No integral gain: JSBSim's integration rule does not matter; no ground test: no
        # integral on the ground to tell apart.
        self.assertFalse(any("Adams-Bashforth" in n or "on the ground" in n for n in notes), notes)

    def assert_no_wing_leveller(self, autopilot, why):
        wl, notes = self.wing_leveller(autopilot)
        self.assertIsNone(wl)
        self.assertTrue(any(n.startswith("JSBSim <autopilot> 'testap' is not translated: no wing "
                                         "leveller (") and why in n for n in notes), notes)
        # Nothing carries the autopilot's output: the FCS input stays listed.
        self.assertTrue(any("input ap/aileron_cmd" in n and "not translated" in n for n in notes))

    def test_a_gain_property_without_default_gives_no_wing_leveller(self):
        self.assert_no_wing_leveller(
            AUTOPILOT.replace('<property value="17.0"> ap/roll-pid-kd </property>', ""),
            "its kd is property ap/roll-pid-kd, which has no <property value=...> default")

    def test_a_pid_on_another_input_gives_no_wing_leveller(self):
        self.assert_no_wing_leveller(
            AUTOPILOT.replace("<input>attitude/phi-rad</input>", "<input>attitude/theta-rad</input>"),
            "no <pid> reads attitude/phi-rad")

    def test_a_chain_that_misses_the_aileron_gives_no_wing_leveller(self):
        self.assert_no_wing_leveller(
            AUTOPILOT.replace("<output>ap/aileron_cmd</output>", "<output>ap/other_cmd</output>"),
            "'fcs/roll-command-selector' reaches no input of the FCS's aileron chain")

    def test_no_autopilot_no_wing_leveller(self):
        wl, notes = self.wing_leveller(aircraft=ROLL_AIRCRAFT.replace('  <autopilot file="testap"/>\n', ""))
        self.assertIsNone(wl)
        self.assertFalse(any("autopilot" in n or "wing_leveller" in n for n in notes), notes)
        self.assertNotIn("wing_leveller", plain(convert()[0])["flight_controls"])

    def test_pitch_trim_option(self):
        sections, _, _ = convert(pitch_trim=("tab", 0.4))
        t = plain(sections)["flight_controls"]["pitch_trim"]
        self.assertEqual(t, {"kind": "tab", "rate_per_s": 0.4})

    def test_pitch_trim_option_is_checked(self):
        for bad in ("wing:0.1", "tab:0", "tab:x", "tab", "stabiliser:11"):
            with tempfile.TemporaryDirectory() as d:
                with contextlib.redirect_stderr(io.StringIO()) as err:
                    rc = jsbsim2fedsim.main(["x.xml", "-o", os.path.join(d, "x.yaml"), "--pitch-trim", bad])
            self.assertEqual(rc, 1, bad)
            self.assertIn("--pitch-trim", err.getvalue())


if __name__ == "__main__":
    unittest.main()
