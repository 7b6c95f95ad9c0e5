// Calibration of real inceptors against hand computations: the axis law (centre, stops,
// reversal, dead zone, expo, detents), debounced and toggled contacts, the calibration file's
// checks, and `fedsim io calibrate`'s recorder.
#include "io/model/inceptor_calibration.hpp"
#include "common/util/build_paths.hpp"
#include "io/model/inceptor_mapper.hpp"

#include "common/util/config_node.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace fedsim::io {
namespace {

AxisCalibration stick(double dead_zone = 0.0, double expo = 0.0) {
  AxisCalibration a;
  a.source = "ABS_X";
  a.channel = Channel::kAileron;
  a.raw_min = 0.0;
  a.raw_centre = 500.0;  // an off-centre rest: each side scales on its own
  a.raw_max = 1200.0;
  a.dead_zone = dead_zone;
  a.expo = expo;
  return a;
}

TEST(AxisCalibration, BipolarAxisScalesEachSideFromItsCentre) {
  const AxisCalibration a = stick();
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 500.0), 0.0);
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 1200.0), 1.0);
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 0.0), -1.0);
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 850.0), 0.5);    // (850 - 500)/700
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 250.0), -0.5);   // (250 - 500)/500
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 5000.0), 1.0);   // beyond the stop: clamped
  EXPECT_DOUBLE_EQ(calibrate_axis(a, std::numeric_limits<double>::quiet_NaN()), 0.0);
}

TEST(AxisCalibration, ReversalDeadZoneAndExpo) {
  AxisCalibration a = stick(0.1, 0.5);
  // x = 0.5 -> dead zone (0.5 - 0.1)/0.9 = 0.4444 -> expo 0.5 x + 0.5 x^3.
  const double x = (0.5 - 0.1) / 0.9;
  EXPECT_NEAR(calibrate_axis(a, 850.0), 0.5 * x + 0.5 * x * x * x, 1e-15);
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 540.0), 0.0);  // x = 0.057: inside the dead zone
  EXPECT_DOUBLE_EQ(calibrate_axis(a, 1200.0), 1.0);  // full travel kept
  a.reversed = true;
  EXPECT_NEAR(calibrate_axis(a, 850.0), -(0.5 * x + 0.5 * x * x * x), 1e-15);
}

TEST(AxisCalibration, UnipolarAxisWithDetentsSnapsTheFlapLever) {
  AxisCalibration flaps;
  flaps.source = "ABS_RZ";
  flaps.channel = Channel::kFlaps;
  flaps.raw_min = 0;
  flaps.raw_max = 255;
  flaps.reversed = true;  // lever forward = flaps up reads 255
  flaps.detents = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
  flaps.detent_capture = 0.05;
  EXPECT_DOUBLE_EQ(calibrate_axis(flaps, 255.0), 0.0);
  EXPECT_DOUBLE_EQ(calibrate_axis(flaps, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(calibrate_axis(flaps, 255.0 * (1.0 - 0.35)), 1.0 / 3.0);  // 0.35: captured
  EXPECT_NEAR(calibrate_axis(flaps, 255.0 * 0.5), 0.5, 1e-12);              // between: as read
  AxisCalibration throttle;
  throttle.channel = Channel::kThrottle1;
  throttle.raw_min = -32768;
  throttle.raw_max = 32767;
  EXPECT_NEAR(calibrate_axis(throttle, 0.0), 32768.0 / 65535.0, 1e-15);
}

TEST(AxisCalibration, BadCalibrationsAreNamed) {
  AxisCalibration a = stick();
  a.raw_centre = 1200.0;  // at a stop
  EXPECT_THROW(a.validate(""), std::invalid_argument);
  a = stick();
  a.dead_zone = 0.6;
  EXPECT_THROW(a.validate(""), std::invalid_argument);
  a = stick();
  a.raw_max = std::numeric_limits<double>::infinity();
  EXPECT_THROW(a.validate(""), std::invalid_argument);
  EXPECT_NO_THROW(stick().validate(""));
}

TEST(Debouncer, TakesALevelOnlyOnceItHasHeld) {
  Debouncer d(0.02);
  EXPECT_FALSE(d.update(0.000, true));
  EXPECT_FALSE(d.update(0.005, false));  // bounce: the pending change restarts
  EXPECT_FALSE(d.update(0.010, true));
  EXPECT_FALSE(d.update(0.025, true));
  EXPECT_TRUE(d.update(0.0305, true));   // held 20 ms (since 0.010)
  EXPECT_TRUE(d.update(0.031, false));   // a release must hold too
}

TEST(InceptorMapper, MapsAxesAndContactsWithToggleAndCountsTheRest) {
  InceptorCalibration c;
  c.axes.push_back(stick());
  DiscreteCalibration trigger;
  trigger.source = "BTN_TRIGGER";
  trigger.channel = Channel::kApDisconnect;
  trigger.debounce_s = 0.0;
  DiscreteCalibration gear;
  gear.source = "BTN_THUMB";
  gear.channel = Channel::kGearDown;
  gear.mode = DiscreteMode::kToggle;
  gear.debounce_s = 0.0;
  c.discretes = {trigger, gear};
  InceptorMapper m(c);
  ControlInputs in = default_controls();
  in[Channel::kAileron] = 0.3;
  m.apply(0.0, in);
  EXPECT_EQ(in[Channel::kAileron], 0.3);  // no reading yet: left as it was
  m.axis("ABS_X", 850.0);
  m.axis("ABS_Y", 3.0);  // not calibrated
  m.axis("ABS_X", std::numeric_limits<double>::quiet_NaN());
  m.contact("BTN_TRIGGER", true, 0.0);
  m.contact("BTN_THUMB", true, 0.0);
  m.apply(0.0, in);
  EXPECT_DOUBLE_EQ(in[Channel::kAileron], 0.5);
  EXPECT_EQ(in[Channel::kApDisconnect], 1.0);
  EXPECT_EQ(in[Channel::kGearDown], 1.0);
  m.contact("BTN_TRIGGER", false, 0.1);
  m.contact("BTN_THUMB", false, 0.1);
  m.apply(0.1, in);
  EXPECT_EQ(in[Channel::kApDisconnect], 0.0);
  EXPECT_EQ(in[Channel::kGearDown], 1.0);  // a toggle stays
  m.contact("BTN_THUMB", true, 0.2);
  m.apply(0.2, in);
  EXPECT_EQ(in[Channel::kGearDown], 0.0);  // second press: gear up
  EXPECT_EQ(m.unmapped_readings(), 1u);
  EXPECT_EQ(m.rejected_readings(), 1u);
}

TEST(InceptorCalibrationFile, RoundTripsAndRejectsBadFilesByField) {
  const std::string text = R"(fedsim_inceptor_calibration: 1
device_name: "Example Stick"
axes:
  - {source: ABS_X, channel: aileron, raw_min: 0, raw_centre: 500, raw_max: 1200, dead_zone: 0.05, expo: 0.2}
  - {source: ABS_RZ, channel: flaps, raw_min: 0, raw_max: 255, reversed: true, detents: [0, 0.5, 1], detent_capture: 0.04}
discretes:
  - {source: BTN_TRIGGER, channel: ap_disconnect, debounce_ms: 10}
  - {source: BTN_THUMB, channel: gear_down, mode: toggle}
)";
  const InceptorCalibration c = InceptorCalibration::parse(text, "stick.yaml");
  ASSERT_EQ(c.axes.size(), 2u);
  EXPECT_EQ(c.device_name, "Example Stick");
  EXPECT_EQ(c.axes[1].channel, Channel::kFlaps);
  EXPECT_DOUBLE_EQ(c.discretes[0].debounce_s, 0.01);
  EXPECT_EQ(c.discretes[1].mode, DiscreteMode::kToggle);
  const InceptorCalibration back = InceptorCalibration::parse(c.to_yaml(), "written.yaml");
  ASSERT_EQ(back.axes.size(), 2u);
  EXPECT_EQ(back.axes[0].raw_centre, 500.0);
  EXPECT_EQ(back.axes[1].detents, c.axes[1].detents);
  EXPECT_EQ(back.discretes[1].mode, DiscreteMode::kToggle);

  auto expect_error = [&](const std::string& from, const std::string& to, const std::string& words) {
    std::string bad = text;
    const auto at = bad.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    try {
      InceptorCalibration::parse(bad, "stick.yaml");
      ADD_FAILURE() << "accepted: " << to;
    } catch (const util::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("stick.yaml"), std::string::npos) << e.what();
    }
  };
  expect_error("channel: aileron", "channel: ailerons", "unknown channel 'ailerons'");
  expect_error("raw_centre: 500", "raw_centre: 1200", "raw_centre");
  expect_error("raw_max: 1200", "raw_max: .nan", "raw_max");
  expect_error("dead_zone: 0.05", "dead_zone: 0.7", "dead_zone");
  expect_error("detents: [0, 0.5, 1]", "detents: [0, 1, 0.5]", "increasing");
  expect_error("source: BTN_THUMB, channel: gear_down", "source: BTN_THUMB, channel: aileron", "driven twice");
  expect_error("source: BTN_THUMB", "source: BTN_TRIGGER", "mapped twice");
  expect_error("mode: toggle", "mode: latch", "momentary");
  expect_error("debounce_ms: 10", "debounce_ms: 5000", "debounce_ms");
  expect_error("fedsim_inceptor_calibration: 1", "fedsim_inceptor_calibration: 2", "fedsim_inceptor_calibration");
}

TEST(CalibrationRecorder, RecordsTheStopsAndTheRestAndRefusesAnAxisNotMoved) {
  CalibrationRecorder r;
  r.start("ABS_Y", Channel::kElevator, 0, 1023);
  for (double v : {512.0, 300.0, 10.0, 700.0, 1015.0, 520.0}) r.observe(v);
  const AxisCalibration a = r.finish(515.0);
  EXPECT_EQ(a.raw_min, 10.0);
  EXPECT_EQ(a.raw_max, 1015.0);
  EXPECT_EQ(a.raw_centre, 515.0);
  EXPECT_NO_THROW(a.validate(""));
  r.start("ABS_Y", Channel::kElevator, 0, 1023);
  for (double v : {500.0, 540.0}) r.observe(v);
  EXPECT_THROW(r.finish(520.0), std::runtime_error);  // barely moved
  r.start("ABS_Y", Channel::kElevator, 0, 1023);
  for (double v : {0.0, 1023.0}) r.observe(v);
  EXPECT_THROW(r.finish(1020.0), std::runtime_error);  // a centred control resting at a stop
  r.start("ABS_Z", Channel::kThrottle1, 0, 255);
  for (double v : {0.0, 255.0}) r.observe(v);
  EXPECT_NO_THROW(r.finish(255.0));  // a throttle rests where it was left
}

TEST(ShippedInceptorFiles, TheExampleCalibrationAndTheC172InterfaceLoad) {
  const InceptorCalibration c = InceptorCalibration::load_file(fedsim::util::data_dir() + "/inceptors/example_stick.yaml");
  EXPECT_EQ(c.axes.size(), 5u);
  EXPECT_EQ(c.discretes.size(), 3u);
}

}  // namespace
}  // namespace fedsim::io
