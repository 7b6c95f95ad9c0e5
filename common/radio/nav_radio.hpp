// VHF NAV radio: the tuner and receiver of one NAV channel (seed 6.6-6.8). Tuned to a frequency
// with an OBS course, it finds the stations on that frequency (StationSource), receives the
// nearest one that reaches the aircraft, and gives its VOR or localizer signal, the glide slope of
// that ILS and the DME paired with the frequency.
//
// Inputs: NavTuning (frequency [kHz], OBS course magnetic [rad]), AircraftPose; the
// StationSource and the StationOutages given at construction (held by reference: they must
// outlive the radio). Output: NavReading.
// Selection: of the VORs (VOR, VOR-DME, VORTAC) and ILS localizers on the frequency, those
// received (on the air, inside the service volume or coverage, in the radio line of sight) are
// candidates and the nearest (geodesic distance) is taken; the DME is chosen the same way among
// the DMEs on the frequency (VOR-DME, VORTAC, DME, TACAN, ILS-DME), independently, as an
// interrogator channel-paired with the VHF frequency is. When nothing is received the reading
// carries the status of the nearest station on the frequency (kNoStation when there is none).
// Failures: set_failed(true) makes every part kReceiverFailed; a station (or its DME or glide
// slope) off the air is not received.
// Per-frame inputs are not thrown on: a frequency outside 108.00-117.95 MHz gives kNotTuned, a
// bad pose or OBS kInvalidInput. A bad station record throws std::invalid_argument.
#pragma once

#include "common/radio/aircraft_pose.hpp"
#include "common/radio/dme_receiver.hpp"
#include "common/radio/glide_slope_receiver.hpp"
#include "common/radio/localizer_receiver.hpp"
#include "common/radio/signal_status.hpp"
#include "common/radio/station_outages.hpp"
#include "common/radio/station_source.hpp"
#include "common/radio/vor_receiver.hpp"

#include <cstdint>
#include <string_view>

namespace fedsim::radio {

inline constexpr std::uint32_t kNavBandLowKhz = 108000;   // ICAO Annex 10 Vol V 4.2
inline constexpr std::uint32_t kNavBandHighKhz = 117950;

struct NavTuning {
  std::uint32_t frequency_khz = 0;       // [kHz], e.g. 115800
  double obs_course_magnetic_rad = 0.0;  // OBS [rad] (used for VORs; a localizer ignores it)
};

enum class NavSignal : std::uint8_t { kNone, kVor, kLocalizer };

struct NavReading {
  NavSignal signal = NavSignal::kNone;  // which course signal is received
  SignalStatus status = SignalStatus::kNoStation;  // of the course signal (why none, if none)
  VorReading vor;                  // meaningful when signal == kVor
  LocalizerReading localizer;      // meaningful when signal == kLocalizer
  GlideSlopeReading glide_slope;   // of the received localizer's ILS; kNoStation otherwise
  DmeReading dme;                  // the DME received on the frequency, if any
  const nav::IlsApproach* approach = nullptr;  // the received ILS (storage of the StationSource)

  bool valid() const { return status == SignalStatus::kValid; }
  std::string_view ident() const;
  /// CDI: -1..1 full scale, + = fly right; 0 when not valid.
  double course_deviation() const;
  /// The course the CDI refers to, true [rad]: the OBS course with the VOR's variation, or the
  /// localizer's front course; 0 when not valid.
  double course_true_rad() const;
  /// From the aircraft to the VOR or localizer antenna, true [rad]; 0 when not valid.
  double bearing_to_station_true_rad() const;
};

class NavRadio {
 public:
  NavRadio(const StationSource& source, const StationOutages& outages,
           VorReceiverSettings vor_settings = {});

  void set_failed(bool failed) { failed_ = failed; }
  bool failed() const { return failed_; }

  NavReading receive(const NavTuning& tuning, const AircraftPose& pose) const;

 private:
  void receive_course(const StationsOnFrequency& stations, const NavTuning& tuning,
                      const AircraftPose& pose, NavReading& reading) const;
  void receive_glide_slope(const AircraftPose& pose, NavReading& reading) const;
  DmeReading receive_dme(const StationsOnFrequency& stations, const AircraftPose& pose) const;

  const StationSource* source_;
  const StationOutages* outages_;
  VorReceiver vor_;
  LocalizerReceiver localizer_;
  GlideSlopeReceiver glide_slope_;
  DmeReceiver dme_;
  bool failed_ = false;
};

}  // namespace fedsim::radio
