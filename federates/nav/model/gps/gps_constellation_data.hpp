// The GPS baseline 24-slot constellation (seed 6.11), as published in the GPS Standard
// Positioning Service (SPS) Performance Standard: 5th edition (April 2020), Table 3.2-1
// "Baseline 24-Slot Constellation Slot Assignments as of the Defined Epoch"; the same slots and
// epoch as the 3rd edition (October 2001), Table 3-1, from which the figures below were
// checked. Slots are given by the right ascension of the ascending node (RAAN) and the argument
// of latitude at the epoch; the orbits are circular (eccentricity 0.00-0.02 in the standard),
// semi-major axis 26,559.7 km, inclination 55 deg.
// Epoch: 0000Z, 1 July 1993; Greenwich hour angle at the epoch 18 h 36 min 14.4 s; referenced
// to FK5/J2000.00 coordinates.
// The expandable slots of the 2008/2020 editions (Table 3.2-2: B1, D2 and F2 split into fore
// and aft slots) are not included: their figures could not be checked here.
// Units as printed in the standard (degrees, km); converted to SI by GpsConstellation.
#pragma once

#include <array>

namespace fedsim::nav::gps_sps {

struct SlotAssignment {
  const char* slot;                  // plane letter A-F and slot number 1-4
  double raan_deg;                   // right ascension of the ascending node at the epoch
  double argument_of_latitude_deg;   // at the epoch
};

inline constexpr std::array<SlotAssignment, 24> kBaselineSlots = {{
    {"A1", 272.847, 268.126}, {"A2", 272.847, 161.786}, {"A3", 272.847, 11.676},
    {"A4", 272.847, 41.806},  {"B1", 332.847, 80.956},  {"B2", 332.847, 173.336},
    {"B3", 332.847, 309.976}, {"B4", 332.847, 204.376}, {"C1", 32.847, 111.876},
    {"C2", 32.847, 11.796},   {"C3", 32.847, 339.666},  {"C4", 32.847, 241.556},
    {"D1", 92.847, 135.226},  {"D2", 92.847, 265.446},  {"D3", 92.847, 35.156},
    {"D4", 92.847, 167.356},  {"E1", 152.847, 197.046}, {"E2", 152.847, 302.596},
    {"E3", 152.847, 66.066},  {"E4", 152.847, 333.686}, {"F1", 212.847, 238.886},
    {"F2", 212.847, 345.226}, {"F3", 212.847, 105.206}, {"F4", 212.847, 135.346},
}};

inline constexpr double kSemiMajorAxisKm = 26559.7;
inline constexpr double kInclinationDeg = 55.0;
// Greenwich hour angle of the vernal equinox at the epoch: 18 h 36 min 14.4 s of time.
inline constexpr double kGreenwichHourAngleAtEpochHours = 18.0 + 36.0 / 60.0 + 14.4 / 3600.0;
inline constexpr double kDegreesPerHourOfAngle = 15.0;

// Speed of light used by GPS (IS-GPS-200, section 20.3.4.3) [m/s]. common/units has no speed
// of light yet; this is its only statement in fedsim.
inline constexpr double kSpeedOfLightMps = 299792458.0;

}  // namespace fedsim::nav::gps_sps
