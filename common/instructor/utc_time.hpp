// The instructor's UTC date and time of day (seed 9.4.5: the time of day lights the visual scene),
// as typed ("2026-12-22T01:30:00") and as carried (year, month, day, seconds since midnight).
#pragma once

#include <optional>
#include <string>

namespace fedsim::instructor {

struct UtcTime {
  int year = 2000;
  int month = 1;                    // 1..12
  int day = 1;                      // 1..days in that month
  double seconds_of_day = 43200.0;  // UTC seconds since midnight, 0..86400 [s]
};

/// The range fedsim accepts (the sun's position is accurate over it).
inline constexpr int kFirstYear = 1800;
inline constexpr int kLastYear = 2200;

/// Days in a month of the Gregorian calendar (0 for a month outside 1..12).
int days_in_month(int year, int month);

/// "" if `t` is a real date within kFirstYear..kLastYear and seconds within [0, 86400];
/// otherwise what is wrong, naming the field ("day 31 is past the end of month 4").
std::string utc_time_problem(const UtcTime& t);

/// "YYYY-MM-DDTHH:MM:SS" (UTC; the seconds may have a fraction); nullopt for anything malformed or
/// out of range.
std::optional<UtcTime> parse_utc(const std::string& text);

}  // namespace fedsim::instructor
