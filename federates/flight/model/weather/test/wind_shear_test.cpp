// Tests of the Oseguera-Bowles microburst: calibration of the peak outflow, zero flow at the
// ground, radial symmetry, downdraft in the core and mass conservation.
#include "flight/model/weather/wind_shear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::flight {
namespace {

WindShear::Params burst() {
  WindShear::Params p;
  p.centre_north_m = 3000.0;
  p.centre_east_m = -500.0;
  p.downdraft_radius_m = 1000.0;
  p.max_outflow_mps = 20.0;
  p.outflow_height_scale_m = 200.0;
  p.boundary_layer_height_scale_m = 30.0;
  return p;
}

// Outward horizontal speed at distance r east of the centre.
double outflow(const WindShear& ws, double r_m, double z_m) {
  const WindShear::Params& p = ws.params();
  return ws.wind_ned_mps(p.centre_north_m, p.centre_east_m + r_m, z_m).y();
}

TEST(WindShear, PeakOutflowIsWhereTheModelSaysAndAsLargeAsAsked) {
  const WindShear ws(burst());
  // z_m = ln(z*/eps) z* eps / (z* - eps) = 66.96 m; r = 1.1209 R.
  EXPECT_NEAR(ws.peak_outflow_height_m(), std::log(200.0 / 30.0) * 6000.0 / 170.0, 1e-9);
  EXPECT_NEAR(ws.peak_outflow_radius_m(), 1120.9, 0.1);
  const double z_m = ws.peak_outflow_height_m(), r_m = ws.peak_outflow_radius_m();
  EXPECT_NEAR(outflow(ws, r_m, z_m), 20.0, 1e-9);
  // It is the maximum: nearby points are slower.
  for (double dr : {-100.0, 100.0}) EXPECT_LT(outflow(ws, r_m + dr, z_m), 20.0);
  for (double dz : {-10.0, 10.0}) EXPECT_LT(outflow(ws, r_m, z_m + dz), 20.0);
}

TEST(WindShear, CalmAtTheGroundAndDownwardInTheCore) {
  const WindShear ws(burst());
  EXPECT_EQ(ws.wind_ned_mps(3000.0, 0.0, 0.0), Eigen::Vector3d::Zero());
  EXPECT_EQ(ws.wind_ned_mps(3000.0, 0.0, -5.0), Eigen::Vector3d::Zero());
  const Eigen::Vector3d core = ws.wind_ned_mps(3000.0, -500.0, 1500.0);
  EXPECT_NEAR(core.head<2>().norm(), 0.0, 1e-12);  // on the axis: no horizontal flow
  EXPECT_GT(core.z(), 0.0);                        // NED down: a downdraft
  // Well above the outflow the core downdraft tends to lambda (z* - eps).
  EXPECT_NEAR(core.z(), ws.core_downdraft_mps(), 1e-3 * ws.core_downdraft_mps());
  EXPECT_GT(ws.core_downdraft_mps(), 10.0);
}

TEST(WindShear, RadialOutflowIsAxisymmetric) {
  const WindShear ws(burst());
  const double speed = outflow(ws, 800.0, 50.0);
  for (double angle = 0.0; angle < 6.28; angle += 0.7) {
    const Eigen::Vector3d w =
        ws.wind_ned_mps(3000.0 + 800.0 * std::cos(angle), -500.0 + 800.0 * std::sin(angle), 50.0);
    EXPECT_NEAR(w.x(), speed * std::cos(angle), 1e-9);
    EXPECT_NEAR(w.y(), speed * std::sin(angle), 1e-9);
  }
  // An aircraft crossing the burst meets a headwind, then a downdraft, then a tailwind.
  EXPECT_LT(ws.wind_ned_mps(3000.0 - 1200.0, -500.0, 60.0).x(), -5.0);
  EXPECT_GT(ws.wind_ned_mps(3000.0 + 1200.0, -500.0, 60.0).x(), 5.0);
}

TEST(WindShear, FlowConservesMass) {
  // Incompressible: du_n/dn + du_e/de + du_up/dz = 0, checked by central differences.
  const WindShear ws(burst());
  const double h = 0.01;
  for (double r : {50.0, 600.0, 1100.0, 2500.0}) {
    for (double z : {5.0, 60.0, 300.0}) {
      const double n = 3000.0 + 0.6 * r, e = -500.0 + 0.8 * r;
      const double dun =
          (ws.wind_ned_mps(n + h, e, z).x() - ws.wind_ned_mps(n - h, e, z).x()) / (2 * h);
      const double due =
          (ws.wind_ned_mps(n, e + h, z).y() - ws.wind_ned_mps(n, e - h, z).y()) / (2 * h);
      const double dwup =
          (-ws.wind_ned_mps(n, e, z + h).z() + ws.wind_ned_mps(n, e, z - h).z()) / (2 * h);
      EXPECT_NEAR(dun + due + dwup, 0.0, 1e-6) << "r " << r << " z " << z;
    }
  }
}

TEST(WindShear, NoBurstIsCalm) {
  const WindShear calm;
  EXPECT_EQ(calm.wind_ned_mps(0.0, 0.0, 100.0), Eigen::Vector3d::Zero());
  WindShear::Params p = burst();
  p.max_outflow_mps = 0.0;
  EXPECT_EQ(WindShear(p).wind_ned_mps(3000.0, 500.0, 60.0), Eigen::Vector3d::Zero());
}

TEST(WindShear, ValidateNamesTheBadField) {
  WindShear::Params p = burst();
  p.outflow_height_scale_m = 20.0;  // below eps
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("outflow_height_scale_m"), std::string::npos);
  }
  p = burst();
  p.downdraft_radius_m = 0.0;
  EXPECT_THROW(WindShear{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
