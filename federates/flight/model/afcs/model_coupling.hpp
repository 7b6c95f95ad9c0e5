// Coupling the AFCS to the flight model and the NAV receivers, in one place (the JSBSim
// "LoadInputs" of the AFCS): what the flight federate's adapter, the batch tests and the
// Monte Carlo use to build AfcsInputs and apply AfcsOutputs. The receivers' types are
// common/radio's (fedsim::radio), the navigation federate's own: in a federation the flight
// adapter builds NAV1's readings from fedsim/navigation_state, in batch ClosedLoopFlight reads the
// receivers in-process, and neither needs the navigation federate's code.
//
//   AircraftOutputs (+ the pack's gear geometry) -> AfcsAircraftState and radio::AircraftPose;
//   LocalizerReading, GlideSlopeReading (+ the approach geometry) -> AfcsIlsSignals;
//   NavReading (NAV1: a VOR with its DME, or an ILS) -> AfcsIlsSignals (its vor part for a VOR);
//   AfcsOutputs -> AircraftControls: the engaged channels replace the pilot's.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/approach_geometry.hpp"
#include "common/radio/glide_slope_receiver.hpp"
#include "common/radio/localizer_receiver.hpp"
#include "common/radio/nav_radio.hpp"
#include "flight/model/afcs/afcs_inputs.hpp"
#include "flight/model/afcs/afcs_outputs.hpp"
#include "flight/model/aircraft/aircraft_controls.hpp"
#include "flight/model/aircraft/aircraft_outputs.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

#include <vector>

namespace fedsim::flight::afcs {

/// Which ground contacts are the main gear and which the nose gear: wheels aft of the pack's
/// empty CG are main wheels, wheels ahead of it the nose (or tail) wheel.
struct GearGeometry {
  std::vector<std::size_t> main_contacts;
  std::vector<std::size_t> nose_contacts;
  /// Throws std::invalid_argument when the pack has no wheel aft of its CG.
  static GearGeometry of(const AircraftPack& pack);
};

/// The main-gear height above the runway plane [m]: the lowest main contact point (uncompressed,
/// so 0 at first contact; negative while the struts are compressed), what a radio altimeter
/// calibrated to the wheels reads.
double main_gear_height_m(const AircraftOutputs& outputs, const AircraftPack& pack,
                          const GearGeometry& gear);

/// The AFCS aircraft port: attitude, rates (relative to the earth), air data, the lateral
/// specific force at the CG, the ground track and its acceleration, altitude (the geodetic height: the flat-earth model's MSL), radio height,
/// weight on wheels and the pilot's present primary commands.
AfcsAircraftState afcs_aircraft_state(const AircraftOutputs& outputs, const AircraftPack& pack,
                                      const GearGeometry& gear, const AircraftControls& pilot);

/// The pose the NAV receivers read (the CG stands for the antennas).
radio::AircraftPose nav_pose(const AircraftOutputs& outputs);

/// The AFCS ILS port from the receivers' readings; distance to the threshold along the course
/// from the approach geometry (+ before the threshold).
AfcsIlsSignals ils_signals(const radio::LocalizerReading& localizer, const radio::GlideSlopeReading& glide_slope,
                           const nav::IlsApproach& approach, const radio::ApproachGeometry& geometry,
                           const radio::AircraftPose& pose);

/// The AFCS's VOR port from a NAV receiver's reading: tuned when its course signal is a VOR,
/// the numbers only when valid (the cone-of-confusion flag said as such), the DME when received.
/// `full_scale_rad`: the receiver's CDI full scale (common/radio VorReceiverSettings).
AfcsVorSignals vor_signals(const radio::NavReading& nav, double full_scale_rad);

/// NAV1's reading as the AFCS's NAV port: a localizer with its glide slope (ils_signals() on the
/// received approach) or a VOR (vor_signals()); the other part flagged.
AfcsIlsSignals nav1_signals(const radio::NavReading& nav, const radio::AircraftPose& pose,
                            double vor_full_scale_rad = radio::VorReceiverSettings{}.full_scale_rad);

/// The pilot's controls with the AFCS's engaged channels in their place. The pitch-trim
/// command runs the trim towards its travel end in the commanded sense (the trim system moves
/// at its own rate); stopped, the trim command is held at `trim_position` (the trim's present
/// position, AircraftOutputs::pitch_trim_norm where the model has a trim system).
AircraftControls apply_afcs_outputs(const AfcsOutputs& afcs, const AircraftControls& pilot,
                                    double trim_position);

}  // namespace fedsim::flight::afcs
