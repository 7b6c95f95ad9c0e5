// Runway designators ("28R", "1L", "09"): the number (01-36, the magnetic heading in tens of
// degrees), the letter of parallel runways (L, C, R) and the reciprocal end's designator.
#pragma once

#include <string>

namespace fedsim::visual {

struct RunwayDesignator {
  int number = 0;   // 1..36
  char letter = 0;  // 'L', 'C', 'R' or 0
  /// The two digits as painted: ICAO Annex 14 5.2.2.4 precedes a single digit with a zero.
  std::string painted_number() const;
  /// The reciprocal end's designator: number +- 18, L <-> R, C stays ("28R" -> "10L").
  std::string reciprocal() const;
  std::string text() const;  // as OurAirports writes it: "1L", "28R", "9"
};

/// Parses "28R", "01L", "9"; throws std::invalid_argument naming `where` for anything else
/// (helipads "H1", water lanes "NW" and numbers outside 1..36 are not runways this draws).
RunwayDesignator parse_designator(const std::string& text, const std::string& where);

}  // namespace fedsim::visual
