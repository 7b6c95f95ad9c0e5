#include "common/instructor/utc_time.hpp"

#include <cmath>
#include <cstdio>

namespace fedsim::instructor {

int days_in_month(int year, int month) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) return 0;
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return kDays[month - 1] + (month == 2 && leap ? 1 : 0);
}

std::string utc_time_problem(const UtcTime& t) {
  if (t.year < kFirstYear || t.year > kLastYear) {
    return "year " + std::to_string(t.year) + " is outside " + std::to_string(kFirstYear) + ".." +
           std::to_string(kLastYear);
  }
  if (t.month < 1 || t.month > 12) return "month " + std::to_string(t.month) + " is outside 1..12";
  if (t.day < 1 || t.day > days_in_month(t.year, t.month)) {
    return "day " + std::to_string(t.day) + " does not exist in " + std::to_string(t.year) + "-" +
           std::to_string(t.month);
  }
  if (!(std::isfinite(t.seconds_of_day) && t.seconds_of_day >= 0.0 && t.seconds_of_day <= 86400.0)) {
    return "seconds of day " + std::to_string(t.seconds_of_day) + " is outside 0..86400";
  }
  return {};
}

std::optional<UtcTime> parse_utc(const std::string& text) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double sec = 0.0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%c", &y, &mo, &d, &h, &mi, &sec, &tail) != 6) {
    return std::nullopt;
  }
  if (h < 0 || h > 23 || mi < 0 || mi > 59 || !(sec >= 0.0 && sec < 60.0)) return std::nullopt;
  const UtcTime t{y, mo, d, h * 3600.0 + mi * 60.0 + sec};
  if (!utc_time_problem(t).empty()) return std::nullopt;
  return t;
}

}  // namespace fedsim::instructor
