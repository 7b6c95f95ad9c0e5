// Units and physical constants: the one place fedsim states a conversion factor or a constant of
// nature. SI inside every model; the factors below are for the edges (options, packs, plots,
// displays) where degrees, feet, knots and nautical miles are what people read and type.
//
// Naming: k<From>To<To> multiplies a value in <From> to give <To> (kFtToM * 1000 ft = 304.8 m).
// Exact factors are exact by definition (international foot 1959, nautical mile 1929, standard
// gravity CGPM 1901, pound-mass 1959).
#pragma once

#include <numbers>

namespace fedsim::units {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kHalfPi = 0.5 * std::numbers::pi;

// Angles.
inline constexpr double kDegToRad = std::numbers::pi / 180.0;
inline constexpr double kRadToDeg = 180.0 / std::numbers::pi;
inline constexpr double kRpmToRadps = 2.0 * std::numbers::pi / 60.0;  // rev/min -> rad/s
inline constexpr double kRadpsToRpm = 60.0 / (2.0 * std::numbers::pi);

// Length, speed.
inline constexpr double kFtToM = 0.3048;
inline constexpr double kMToFt = 1.0 / kFtToM;
inline constexpr double kInToM = 0.0254;
inline constexpr double kNmToM = 1852.0;                 // nautical mile
inline constexpr double kMToNm = 1.0 / kNmToM;
inline constexpr double kKtToMps = 1852.0 / 3600.0;      // knot
inline constexpr double kMpsToKt = 3600.0 / 1852.0;
inline constexpr double kFpmToMps = kFtToM / 60.0;       // feet per minute (vertical speed)
inline constexpr double kMpsToFpm = 60.0 / kFtToM;

// Mass, force, power, pressure, volume.
inline constexpr double kLbToKg = 0.45359237;            // pound-mass
inline constexpr double kSlugToKg = 14.593902937206364;  // lbf s^2 / ft
inline constexpr double kLbfToN = 4.4482216152605;
inline constexpr double kHpToW = 745.69987158227022;     // mechanical horsepower (550 ft lbf/s)
inline constexpr double kInHgToPa = 3386.389;            // inch of mercury (0 degC)
inline constexpr double kHpaToPa = 100.0;
inline constexpr double kPsfToPa = kLbfToN / (kFtToM * kFtToM);
inline constexpr double kCubicInToM3 = kInToM * kInToM * kInToM;

// Temperature differences and scales.
inline constexpr double kCelsiusZeroK = 273.15;
inline constexpr double kRankineToK = 5.0 / 9.0;

// Constants of nature and standards.
inline constexpr double kStandardGravityMps2 = 9.80665;  // g0 (CGPM 1901), also US 1976's g0

constexpr double deg_to_rad(double deg) { return deg * kDegToRad; }
constexpr double rad_to_deg(double rad) { return rad * kRadToDeg; }

}  // namespace fedsim::units
