#include "fedsim/nav_cli.hpp"

#include "common/navdb/nav_database.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace fedsim::launcher {

namespace {

using nav::IlsApproach;
using nav::Navaid;
using nav::NavaidType;
using nav::RunwayEndRecord;
using units::kRadToDeg;

constexpr int kExitNotFound = 1;
constexpr int kExitBadArgument = 2;
constexpr double kMaxRadiusNm = 10800.0;  // half the earth's circumference

std::string format(const char* pattern, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

/// "N37 37.17" / "W122 22.44": degrees and decimal minutes, as on charts.
std::string degrees_minutes(double angle_rad, char positive, char negative, int degree_digits) {
  const double deg = std::abs(angle_rad * kRadToDeg);
  int whole = static_cast<int>(deg);
  double minutes = (deg - whole) * 60.0;
  if (std::round(minutes * 100.0) >= 6000.0) {  // 59.999 rounds up to the next degree
    ++whole;
    minutes = 0.0;
  }
  return format("%c%0*d %05.2f", angle_rad < 0.0 ? negative : positive, degree_digits, whole,
                minutes);
}

std::string position_text(const nav::GeoPoint& p) {
  return degrees_minutes(p.lat_rad, 'N', 'S', 2) + " " + degrees_minutes(p.lon_rad, 'E', 'W', 3);
}

/// VHF in MHz, NDB in kHz, "-" for a TACAN channel without a VHF pairing.
std::string frequency_text(const Navaid& n) {
  if (nav::is_ndb(n.type)) return format("%u kHz", n.frequency_khz);
  if (n.frequency_khz == 0) return "-";
  return format("%.2f MHz", n.frequency_khz / 1000.0);
}

std::string elevation_text(const Navaid& n) {
  return n.elevation_known ? format("%.0f", n.position.elevation_m * units::kMToFt) : "-";
}

std::string variation_text(double variation_rad) {
  const double deg = variation_rad * kRadToDeg;
  return format("%.1f%c", std::abs(deg), deg < 0.0 ? 'W' : 'E');
}

int heading_deg(double angle_rad) {
  const int deg = static_cast<int>(std::lround(std::fmod(angle_rad * kRadToDeg + 720.0, 360.0)));
  return deg == 0 ? 360 : deg;  // compass convention: 360, not 000
}

std::string navaid_line(const Navaid& n) {
  return format("%-5s %-7s %-10s %-4s %-22.22s %s %7s %-2s %-6s", n.ident.c_str(),
                std::string(nav::navaid_type_name(n.type)).c_str(), frequency_text(n).c_str(),
                n.dme_channel.empty() ? "-" : n.dme_channel.c_str(), n.name.c_str(),
                position_text(n.position).c_str(), elevation_text(n).c_str(), n.country.c_str(),
                variation_text(n.magnetic_variation_rad).c_str());
}

const char* kNavaidHeader =
    "IDENT TYPE    FREQ       CH   NAME                   LAT       LON        ELEV_FT CC VAR";

void print_runways(const std::vector<RunwayEndRecord>& ends, std::ostream& out) {
  out << "RWY  THRESHOLD            ELEV_FT HDG_T LENGTH_FT WIDTH_FT DISPL_FT SURFACE LIT CLOSED\n";
  for (const auto& r : ends) {
    out << format("%-4s %s %7s   %03d %9.0f %8.0f %8.0f %-7s %-3s %s\n", r.runway.c_str(),
                  position_text(r.threshold).c_str(),
                  r.elevation_known ? format("%.0f", r.threshold.elevation_m * units::kMToFt).c_str()
                                    : "-",
                  heading_deg(r.heading_true_rad), r.length_m * units::kMToFt,
                  r.width_m * units::kMToFt, r.displaced_threshold_m * units::kMToFt,
                  r.surface.c_str(), r.lighted ? "yes" : "no", r.closed ? "yes" : "no");
  }
}

void print_ils(const std::vector<IlsApproach>& approaches, std::ostream& out) {
  out << "ARPT RWY  IDENT FREQ       CRS_M CRS_T GS_DEG TCH_FT CAT DME\n";
  for (const auto& a : approaches) {
    out << format("%-4s %-4s %-5s %.2f MHz   %03d   %03d %6.2f %6.0f %-3s %s\n", a.airport.c_str(),
                  a.runway.c_str(), a.ident.c_str(), a.frequency_khz / 1000.0,
                  heading_deg(a.course_magnetic_rad), heading_deg(a.course_true_rad),
                  a.glide_path_angle_rad * kRadToDeg,
                  a.threshold_crossing_height_m * units::kMToFt, a.category.c_str(),
                  a.has_dme ? "yes" : "no");
  }
}

/// The set of types a "--type VOR,NDB" list names; throws std::invalid_argument naming a bad one.
std::set<NavaidType> parse_types(const std::string& list) {
  std::set<NavaidType> types;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto type = nav::parse_navaid_type(item);
    if (!type) {
      throw std::invalid_argument("--type: '" + item +
                                  "' is not a station type (VOR, VOR-DME, VORTAC, DME, TACAN, "
                                  "NDB, NDB-DME)");
    }
    types.insert(*type);
  }
  if (!list.empty() && types.empty()) throw std::invalid_argument("--type: empty list");
  return types;
}

void check_query(const NavNearQuery& q) {
  if (!std::isfinite(q.lat_deg) || q.lat_deg < -90.0 || q.lat_deg > 90.0) {
    throw std::invalid_argument(format("latitude %g deg: must be a number in [-90, 90]", q.lat_deg));
  }
  if (!std::isfinite(q.lon_deg) || q.lon_deg < -180.0 || q.lon_deg > 180.0) {
    throw std::invalid_argument(
        format("longitude %g deg: must be a number in [-180, 180]", q.lon_deg));
  }
  if (!std::isfinite(q.radius_nm) || q.radius_nm <= 0.0 || q.radius_nm > kMaxRadiusNm) {
    throw std::invalid_argument(
        format("--radius-nm %g: must be a number in (0, %.0f]", q.radius_nm, kMaxRadiusNm));
  }
}

}  // namespace

int nav_find(const std::string& db_path, const std::string& query, std::ostream& out,
             std::ostream& err) {
  if (query.empty()) {
    err << "fedsim nav find: give an ident or an airport\n";
    return kExitBadArgument;
  }
  try {
    const nav::NavDatabase db = nav::NavDatabase::open(db_path);
    const auto navaids = db.find(query);
    const auto localizers = db.ils_by_ident(query);
    const auto runways = db.airport_runways(query);
    const auto approaches = db.airport_ils(query);
    if (!navaids.empty()) {
      out << "Navaids " << nav::upper_ascii(query) << " (" << navaids.size() << "):\n"
          << kNavaidHeader << '\n';
      for (const auto& n : navaids) out << navaid_line(n) << '\n';
    }
    if (!localizers.empty()) {
      out << "Localizers " << nav::upper_ascii(query) << ":\n";
      print_ils(localizers, out);
    }
    if (!runways.empty()) {
      out << "Airport " << runways.front().airport << ": " << runways.size() << " runway ends\n";
      print_runways(runways, out);
      if (approaches.empty()) {
        out << "No ILS approaches in the database for " << runways.front().airport << ".\n";
      } else {
        print_ils(approaches, out);
      }
    }
    if (navaids.empty() && localizers.empty() && runways.empty()) {
      err << "fedsim nav find: no navaid, localizer or airport '" << query << "' in " << db_path
          << '\n';
      return kExitNotFound;
    }
    return 0;
  } catch (const std::exception& e) {
    err << "fedsim nav find: " << e.what() << '\n';
    return kExitBadArgument;
  }
}

int nav_near(const std::string& db_path, const NavNearQuery& query, std::ostream& out,
             std::ostream& err) {
  try {
    check_query(query);
    const std::set<NavaidType> types = parse_types(query.types);
    const nav::NavDatabase db = nav::NavDatabase::open(db_path);
    const nav::GeoPoint centre{query.lat_deg * units::kDegToRad, query.lon_deg * units::kDegToRad,
                               0.0};
    const auto hits = db.within(centre.lat_rad, centre.lon_rad, query.radius_nm * units::kNmToM);
    std::vector<nav::NavaidHit> shown;
    for (const auto& h : hits) {
      if (types.empty() || types.count(h.navaid.type)) shown.push_back(h);
    }
    out << "Within " << format("%g", query.radius_nm) << " NM of " << position_text(centre) << ": "
        << shown.size() << " stations (magnetic bearing: true minus the station's variation)\n";
    if (shown.empty()) return kExitNotFound;
    out << kNavaidHeader << " DIST_NM BRG_T BRG_M\n";
    for (const auto& h : shown) {
      out << navaid_line(h.navaid)
          << format(" %7.1f   %03d   %03d\n", h.distance_m * units::kMToNm,
                    heading_deg(h.bearing_true_rad),
                    heading_deg(h.bearing_true_rad - h.navaid.magnetic_variation_rad));
    }
    return 0;
  } catch (const std::exception& e) {  // a bad argument, or a database that will not open
    err << "fedsim nav near: " << e.what() << '\n';
    return kExitBadArgument;
  }
}

void add_nav_commands(CLI::App& app, int& exit_code, std::ostream& out, std::ostream& err) {
  auto* nav_cmd = app.add_subcommand("nav", "look up the navigation database: navaids, runways, ILS");
  nav_cmd->require_subcommand(1);
  auto db_path = std::make_shared<std::string>(nav::default_database_path());
  nav_cmd->add_option("--db", *db_path, "navigation database (default: the build's)")
      ->capture_default_str();

  auto ident = std::make_shared<std::string>();
  auto* find = nav_cmd->add_subcommand("find", "navaids, localizers or an airport by ident");
  find->add_option("ident", *ident, "navaid ident (SFO), localizer (ISFO) or airport (KSFO)")
      ->required();
  find->callback([db_path, ident, &exit_code, &out, &err] {
    exit_code = nav_find(*db_path, *ident, out, err);
  });

  auto near = std::make_shared<NavNearQuery>();
  auto* near_cmd = nav_cmd->add_subcommand("near", "stations near a position, nearest first");
  near_cmd->add_option("lat_deg", near->lat_deg, "latitude [deg], north positive")->required();
  near_cmd->add_option("lon_deg", near->lon_deg, "longitude [deg], east positive")->required();
  near_cmd->add_option("--radius-nm", near->radius_nm, "search radius [NM]")->capture_default_str();
  near_cmd->add_option("--type", near->types,
                       "station types, comma-separated: VOR,VOR-DME,VORTAC,DME,TACAN,NDB,NDB-DME");
  near_cmd->callback([db_path, near, &exit_code, &out, &err] {
    exit_code = nav_near(*db_path, *near, out, err);
  });
}

}  // namespace fedsim::launcher
