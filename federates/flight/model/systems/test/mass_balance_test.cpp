// Tests of the mass balance: totals and CG, fuel burn from feed tanks, starvation, and the
// inertia tensor about the moving CG.
#include "flight/model/systems/mass_balance.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <string>

#include "flight/model/systems/test/reference_data.hpp"

namespace fedsim::flight {
namespace {

using reference::kLb;

// Inertia about the datum by direct summation, then moved to the CG: a different route
// from the model's (which moves each item to the CG).
Eigen::Matrix3d inertia_about_cg(const MassBalance::Params& p, const MassBalance::Outputs& out) {
  auto about_datum = [](double m, const Eigen::Vector3d& r) {
    return Eigen::Matrix3d(m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose()));
  };
  Eigen::Matrix3d j = p.empty_inertia_kgm2 + about_datum(p.empty_mass_kg, p.empty_cg_m);
  for (const auto& pm : p.point_masses) j += about_datum(pm.mass_kg, pm.position_m);
  for (std::size_t t = 0; t < p.tanks.size(); ++t) {
    j += about_datum(out.tank_contents_kg[t], p.tanks[t].position_m);
  }
  return j - about_datum(out.mass_kg, out.cg_m);
}

TEST(MassBalance, TotalsAndCgOfTheLoadedC172) {
  const MassBalance mb(reference::c172_mass());
  const MassBalance::Outputs& out = mb.outputs();
  // 1454 empty + 686 people and luggage + 260 fuel = 2400 lb.
  EXPECT_NEAR(out.mass_kg, 2400.0 * kLb, 1e-9);
  EXPECT_NEAR(out.fuel_kg, 260.0 * kLb, 1e-12);
  // CG x station (JSBSim inches aft of datum): weighted mean of the item stations.
  const double x_station_in = (1454.0 * 41.0 + 190.0 * 36.0 + 140.0 * 36.0 + 130.0 * 60.0 +
                               106.0 * 60.0 + 120.0 * 95.0 + 260.0 * 48.0) /
                              2400.0;
  EXPECT_NEAR(out.cg_m.x(), -x_station_in * reference::kIn, 1e-12);
  EXPECT_NEAR(
      out.cg_m.y(),
      (-14.0 * 190.0 + 14.0 * 140.0 - 14.0 * 130.0 + 14.0 * 106.0) / 2400.0 * reference::kIn,
      1e-12);
  EXPECT_TRUE(out.inertia_kgm2.isApprox(inertia_about_cg(mb.params(), out), 1e-12));
}

TEST(MassBalance, BurningFuelFromBothWingTanksMovesTheCgForward) {
  MassBalance mb(reference::c172_mass());
  const MassBalance::Outputs before = mb.outputs();
  const double flow_kgps = 0.0091;  // ~ 10 US gal/h of avgas
  const std::array<double, 1> flows = {flow_kgps};
  const double dt = 0.02;
  for (int i = 0; i < 50 * 600; ++i) mb.step(dt, {flows});  // ten minutes
  const MassBalance::Outputs& after = mb.outputs();
  const double burnt = flow_kgps * 600.0;
  EXPECT_NEAR(before.mass_kg - after.mass_kg, burnt, 1e-9);
  EXPECT_NEAR(after.tank_contents_kg[0], after.tank_contents_kg[1], 1e-12);  // equal draw
  EXPECT_NEAR(after.tank_contents_kg[0], 130.0 * kLb - burnt / 2.0, 1e-9);
  // Removing mass at the tank station x_t moves the CG by burnt (x_cg - x_t) / m_after.
  const double x_tank = reference::c172_mass().tanks[0].position_m.x();
  EXPECT_NEAR(after.cg_m.x() - before.cg_m.x(), burnt * (before.cg_m.x() - x_tank) / after.mass_kg,
              1e-12);
  EXPECT_GT(after.cg_m.x(), before.cg_m.x());  // the tanks sit aft of the CG
  EXPECT_NEAR(after.cg_m.y(), before.cg_m.y() * before.mass_kg / after.mass_kg, 1e-12);
  // High wing tanks: less fuel, lower (z down grows) CG and less roll inertia.
  EXPECT_GT(after.cg_m.z(), before.cg_m.z());
  EXPECT_LT(after.inertia_kgm2(0, 0), before.inertia_kgm2(0, 0));
  EXPECT_TRUE(after.inertia_kgm2.isApprox(inertia_about_cg(mb.params(), after), 1e-12));
  EXPECT_FALSE(after.engine_starved[0]);
}

TEST(MassBalance, SharedCentreTankEmptiesThenWingTanksCarryOn) {
  MassBalance mb(reference::b737_mass());
  const double centre0 = 4000.0 * kLb, wing0 = 10000.0 * kLb;
  const double flow = 0.6;  // kg/s per engine, both engines drawing from own wing + centre
  const std::array<double, 2> flows = {flow, flow};
  // Each engine takes half its flow from the centre tank: it empties after centre0 / flow s.
  const double t_centre_empty = centre0 / (2.0 * 0.5 * flow);
  double t = 0.0;
  const double dt = 0.05;
  while (t < t_centre_empty - 1.0) {
    mb.step(dt, {flows});
    t += dt;
  }
  EXPECT_GT(mb.outputs().tank_contents_kg[2], 0.0);
  EXPECT_NEAR(mb.outputs().tank_contents_kg[0], wing0 - 0.5 * flow * t, 1e-6);
  for (int i = 0; i < 200; ++i) {
    mb.step(dt, {flows});
    t += dt;
  }
  EXPECT_EQ(mb.outputs().tank_contents_kg[2], 0.0);
  // Total burn is exact across the hand-over, and the wings stay balanced.
  EXPECT_NEAR(mb.outputs().fuel_kg, 2.0 * wing0 + centre0 - 2.0 * flow * t, 1e-6);
  // Within one step's burn of each other (engine 0 drew the centre tank's last fuel first).
  EXPECT_NEAR(mb.outputs().tank_contents_kg[0], mb.outputs().tank_contents_kg[1], flow * dt);
  EXPECT_NEAR(mb.outputs().cg_m.y(), 0.0, 1e-6);
  EXPECT_FALSE(mb.outputs().engine_starved[0]);
}

TEST(MassBalance, EngineStarvesWhenItsFeedTanksRunDry) {
  MassBalance mb(reference::b737_mass());
  mb.set_tank_contents_kg(0, 1.0);
  mb.set_tank_contents_kg(2, 0.0);
  const std::array<double, 2> flows = {0.5, 0.5};
  mb.step(1.0, {flows});  // engine 0 wants 0.5 kg, has 1 kg
  EXPECT_FALSE(mb.outputs().engine_starved[0]);
  mb.step(2.0, {flows});  // wants 1 kg, has 0.5 kg
  EXPECT_TRUE(mb.outputs().engine_starved[0]);
  EXPECT_FALSE(mb.outputs().engine_starved[1]);
  EXPECT_EQ(mb.outputs().tank_contents_kg[0], 0.0);
  mb.reset();
  EXPECT_FALSE(mb.outputs().engine_starved[0]);
  EXPECT_NEAR(mb.outputs().fuel_kg, 24000.0 * kLb, 1e-9);
}

TEST(MassBalance, SettingsAreClampedAndMoveTheCg) {
  MassBalance mb(reference::c172_mass());
  mb.set_tank_contents_kg(1, 1e6);
  EXPECT_NEAR(mb.outputs().tank_contents_kg[1], 130.0 * kLb, 1e-12);
  mb.set_tank_contents_kg(0, 0.0);  // right tank full, left empty: CG moves right
  EXPECT_GT(mb.outputs().cg_m.y(), 0.0);
  const double before = mb.outputs().mass_kg;
  mb.set_point_mass_kg(4, 0.0);  // unload the luggage
  EXPECT_NEAR(before - mb.outputs().mass_kg, 120.0 * kLb, 1e-9);
  EXPECT_THROW(mb.set_tank_contents_kg(5, 1.0), std::out_of_range);
  EXPECT_THROW(mb.set_point_mass_kg(0, -1.0), std::invalid_argument);
}

TEST(MassBalance, StepRejectsTheWrongNumberOfEngines) {
  MassBalance mb(reference::c172_mass());
  const std::array<double, 2> two = {0.0, 0.0};
  EXPECT_THROW(mb.step(0.02, {two}), std::invalid_argument);
}

TEST(MassBalance, ValidateNamesTheBadField) {
  auto expect_field = [](const MassBalance::Params& p, const std::string& field) {
    try {
      p.validate();
      ADD_FAILURE() << "no exception for " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  MassBalance::Params p = reference::c172_mass();
  p.tanks[1].initial_contents_kg = 1000.0;
  expect_field(p, "tanks[1].initial_contents_kg");
  p = reference::c172_mass();
  p.engine_feeds = {{0, 7}};
  expect_field(p, "engine_feeds[0]");
  p = reference::c172_mass();
  p.empty_inertia_kgm2(0, 0) = -1.0;
  expect_field(p, "empty_inertia_kgm2");
  p = reference::c172_mass();
  p.point_masses[2].mass_kg = -5.0;
  expect_field(p, "point_masses[2].mass_kg");
}

}  // namespace
}  // namespace fedsim::flight
