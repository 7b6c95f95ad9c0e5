#include "visual/model/runway_designator.hpp"

#include "common/util/input_checks.hpp"

#include <cctype>

namespace fedsim::visual {

std::string RunwayDesignator::painted_number() const {
  return (number < 10 ? "0" : "") + std::to_string(number);
}

std::string RunwayDesignator::text() const {
  return std::to_string(number) + (letter != 0 ? std::string(1, letter) : std::string());
}

std::string RunwayDesignator::reciprocal() const {
  const int opposite = number > 18 ? number - 18 : number + 18;
  char other = letter;
  if (letter == 'L') other = 'R';
  if (letter == 'R') other = 'L';
  return std::to_string(opposite) + (other != 0 ? std::string(1, other) : std::string());
}

RunwayDesignator parse_designator(const std::string& text, const std::string& where) {
  std::size_t digits = 0;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  const bool letter_ok =
      text.size() == digits || (text.size() == digits + 1 &&
                                (text.back() == 'L' || text.back() == 'C' || text.back() == 'R'));
  if (digits == 0 || digits > 2 || !letter_ok) {
    util::reject(where, "runway", "'" + text + "' is not a runway designator (01-36 and L/C/R)");
  }
  RunwayDesignator d;
  d.number = std::stoi(text.substr(0, digits));
  if (d.number < 1 || d.number > 36) {
    util::reject(where, "runway", "'" + text + "': the number must be 01-36");
  }
  d.letter = text.size() > digits ? text.back() : 0;
  return d;
}

}  // namespace fedsim::visual
