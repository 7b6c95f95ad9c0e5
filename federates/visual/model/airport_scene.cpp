#include "visual/model/airport_scene.hpp"

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"
#include "visual/model/runway_designator.hpp"
#include "visual/model/runway_frame.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fedsim::visual {

namespace {

constexpr double kPaintLiftM = 0.03;         // markings above the pavement
constexpr double kGroundBelowM = 0.3;        // the ground sphere below the lowest runway end
constexpr double kPieceM = 50.0;             // pavement pieces along the runway
constexpr double kEdgeLightSpacingM = 60.0;  // Annex 14 5.3.9.4

using nav::RunwayEndRecord;

std::string where_of(const RunwayEndRecord& r) {
  return "runway end " + r.airport + " " + r.runway;
}

void check_point(const nav::GeoPoint& p, const std::string& where, const std::string& name) {
  util::require_in_range(p.lat_rad, -units::kHalfPi, units::kHalfPi, where, name + ".lat_rad", "rad");
  util::require_in_range(p.lon_rad, -units::kPi, units::kPi, where, name + ".lon_rad", "rad");
  util::require_in_range(p.elevation_m, -500.0, 9000.0, where, name + ".elevation_m", "m");
}

struct Runway {
  const RunwayEndRecord* a = nullptr;
  const RunwayEndRecord* b = nullptr;  // nullptr: a single-ended record
};

std::vector<Runway> pair_ends(const std::vector<const RunwayEndRecord*>& ends) {
  std::vector<Runway> runways;
  std::vector<bool> used(ends.size(), false);
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    Runway r{ends[i], nullptr};
    const std::string reciprocal =
        parse_designator(ends[i]->runway, where_of(*ends[i])).reciprocal();
    for (std::size_t j = i + 1; j < ends.size(); ++j) {
      if (!used[j] && parse_designator(ends[j]->runway, where_of(*ends[j])).text() == reciprocal) {
        used[j] = true;
        r.b = ends[j];
        break;
      }
    }
    runways.push_back(r);
  }
  return runways;
}

// One runway end's frame and facts, with the runway it belongs to.
struct EndContext {
  const RunwayEndRecord* record;
  RunwayEndOptions options;
  RunwayFrame frame;
  double width_m;
  double landing_distance_m;  // threshold to the stop end
  int index;                  // in Scene::runway_ends
};

class SceneBuilder {
 public:
  SceneBuilder(Scene& scene, const AirportSceneOptions& options)
      : scene_(scene), options_(options) {}

  void add_runway(const Runway& runway);

 private:
  EndContext make_end(const RunwayEndRecord& end, const RunwayEndRecord* opposite, double width_m);
  void add_pavement(const EndContext& a, double from_m, double to_m);
  void add_paint(const EndContext& e, const std::vector<Quad2>& quads);
  void add_lights(const EndContext& e, const std::vector<LightSite>& sites);
  EndMarkings add_end_markings(const EndContext& e);
  void add_end_lights(const EndContext& e, const std::vector<double>& edge_positions_m);
  EndLightingInput lighting_input(const EndContext& e) const;

  Scene& scene_;
  const AirportSceneOptions& options_;
};

RunwayEndOptions options_for(const AirportSceneOptions& options, const std::string& runway) {
  const auto it = options.ends.find(runway);
  return it != options.ends.end() ? it->second : options.default_end;
}

EndContext SceneBuilder::make_end(const RunwayEndRecord& end, const RunwayEndRecord* opposite,
                                  double width_m) {
  RunwayProfile profile;
  profile.start_along_m = -end.displaced_threshold_m;
  profile.start_elevation_m = end.end.elevation_m;
  profile.end_along_m = end.length_m - end.displaced_threshold_m;
  profile.end_elevation_m = opposite != nullptr ? opposite->end.elevation_m : end.end.elevation_m;
  RunwayFrame frame(scene_.frame, end.threshold.lat_rad, end.threshold.lon_rad,
                    end.heading_true_rad, profile);
  const RunwayEndOptions opts = options_for(options_, end.runway);
  RunwayEndInfo info;
  info.airport = end.airport;
  info.designator = end.runway;
  info.threshold_scene_m = frame.scene(0.0, 0.0, 0.0);
  info.threshold_elevation_m = profile.elevation_m(0.0);
  info.heading_true_rad = end.heading_true_rad;
  info.width_m = width_m;
  info.landing_distance_m = end.length_m - end.displaced_threshold_m;
  info.category = opts.category;
  info.approach_lighting = end.lighted ? opts.approach_lighting : ApproachLighting::kNone;
  scene_.runway_ends.push_back(info);
  return {&end,
          opts,
          frame,
          width_m,
          info.landing_distance_m,
          static_cast<int>(scene_.runway_ends.size()) - 1};
}

void SceneBuilder::add_pavement(const EndContext& a, double from_m, double to_m) {
  const int pieces = std::max(1, static_cast<int>(std::ceil((to_m - from_m) / kPieceM)));
  const double half = 0.5 * a.width_m;
  const auto vertex = [&](double along, double right) {
    SurfaceVertex v;
    v.position_scene_m = a.frame.scene(along, right, 0.0).cast<float>();
    v.texture_m = Eigen::Vector2f(static_cast<float>(along), static_cast<float>(right));
    v.material = SurfaceMaterial::kPavement;
    return v;
  };
  for (int i = 0; i < pieces; ++i) {
    const double x0 = from_m + (to_m - from_m) * i / pieces;
    const double x1 = from_m + (to_m - from_m) * (i + 1) / pieces;
    const SurfaceVertex p00 = vertex(x0, -half), p01 = vertex(x0, half), p10 = vertex(x1, -half),
                        p11 = vertex(x1, half);
    scene_.triangles.insert(scene_.triangles.end(), {p00, p10, p11, p00, p11, p01});
  }
}

void SceneBuilder::add_paint(const EndContext& e, const std::vector<Quad2>& quads) {
  for (const Quad2& q : quads) {
    SurfaceVertex v[4];
    for (int k = 0; k < 4; ++k) {
      v[k].position_scene_m =
          e.frame.scene(q.corners[k].x(), q.corners[k].y(), kPaintLiftM).cast<float>();
      v[k].texture_m = q.corners[k].cast<float>();
      v[k].material = SurfaceMaterial::kPaint;
    }
    scene_.triangles.insert(scene_.triangles.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
  }
}

void SceneBuilder::add_lights(const EndContext& e, const std::vector<LightSite>& sites) {
  for (const LightSite& s : sites) {
    const Eigen::Vector3d up = e.frame.up_scene(s.along_m, s.right_m);
    const Eigen::Vector3d forward = e.frame.forward_scene(s.along_m, s.right_m);
    const Eigen::Vector3d right = forward.cross(up);
    const double side = s.right_m > 0.0 ? 1.0 : (s.right_m < 0.0 ? -1.0 : 0.0);
    // Facing this end's traffic (back along the landing direction), turned towards the
    // centreline by the toe-in, raised by the elevation setting.
    const Eigen::Vector3d horizontal =
        -forward * std::cos(s.toe_in_rad) - side * right * std::sin(s.toe_in_rad);
    const Eigen::Vector3d axis =
        horizontal * std::cos(s.elevation_setting_rad) + up * std::sin(s.elevation_setting_rad);
    LightPoint p;
    p.position_scene_m = e.frame.scene(s.along_m, s.right_m, s.height_m).cast<float>();
    p.beam_axis_scene = axis.normalized().cast<float>();
    p.up_scene = up.cast<float>();
    p.colour_rgb = s.colour_rgb;
    p.intensity_cd = s.intensity_cd;
    p.beam_half_width_h_rad = s.beam_half_width_h_rad;
    p.beam_half_width_v_rad = s.beam_half_width_v_rad;
    p.papi_transition_rad = s.papi_transition_rad;
    p.beam = s.beam;
    p.role = s.role;
    p.runway_end = e.index;
    scene_.lights.push_back(p);
  }
}

EndMarkings SceneBuilder::add_end_markings(const EndContext& e) {
  EndMarkingInput in;
  in.designator = parse_designator(e.record->runway, where_of(*e.record));
  in.width_m = e.width_m;
  in.landing_distance_m = e.landing_distance_m;
  in.displaced_threshold_m = e.record->displaced_threshold_m;
  in.category = e.options.category;
  EndMarkings m = end_markings(in);
  add_paint(e, m.quads);
  RunwayEndInfo& info = scene_.runway_ends[e.index];
  info.threshold_stripes = m.threshold_stripes;
  info.aiming_point_m = m.aiming_point ? m.aiming_point->start_m : 0.0;
  return m;
}

EndLightingInput SceneBuilder::lighting_input(const EndContext& e) const {
  EndLightingInput in;
  in.width_m = e.width_m;
  in.threshold_to_stop_end_m = e.landing_distance_m;
  in.runway_start_m = -e.record->displaced_threshold_m;
  in.category = e.options.category;
  in.approach = e.options.approach_lighting;
  in.papi = e.options.papi;
  in.papi_along_m = aiming_point_layout(e.landing_distance_m).start_m;
  in.glide_path_rad = e.options.glide_path_rad;
  in.touchdown_zone_gauge_m = aiming_point_layout(e.landing_distance_m).inner_spacing_m;
  return in;
}

void SceneBuilder::add_end_lights(const EndContext& e,
                                  const std::vector<double>& edge_positions_m) {
  if (!e.record->lighted) {
    scene_.notes.push_back(where_of(*e.record) + ": unlighted, no lights drawn");
    return;
  }
  const EndLightingInput in = lighting_input(e);
  add_lights(e, approach_lights(in));
  add_lights(e, edge_lights(in, edge_positions_m));
  add_lights(e, threshold_lights(in));
  add_lights(e, runway_end_lights(in));
  add_lights(e, centreline_lights(in));
  add_lights(e, touchdown_zone_lights(in));
  add_lights(e, papi_units(in));
  if (in.papi) scene_.runway_ends[e.index].papi_along_m = in.papi_along_m;
}

double width_of(const Runway& r, const AirportSceneOptions& options,
                std::vector<std::string>& notes) {
  if (r.a->width_m > 0.0) return r.a->width_m;
  if (r.b != nullptr && r.b->width_m > 0.0) return r.b->width_m;
  notes.push_back(where_of(*r.a) + ": width unknown, drawn " +
                  std::to_string(options.unknown_width_m) + " m wide");
  return options.unknown_width_m;
}

void SceneBuilder::add_runway(const Runway& runway) {
  const double width = width_of(runway, options_, scene_.notes);
  const EndContext a = make_end(*runway.a, runway.b, width);
  const double start = -runway.a->displaced_threshold_m;
  const double stop = runway.a->length_m - runway.a->displaced_threshold_m;
  add_pavement(a, start, stop);
  const EndMarkings ma = add_end_markings(a);

  double centreline_to = stop - centreline_clearance_m();
  double stripes_to = stop;
  ApproachCategory widest = a.options.category;
  std::vector<double> edge_positions;
  const int gaps = std::max(1, static_cast<int>(std::ceil((stop - start) / kEdgeLightSpacingM)));
  for (int i = 0; i <= gaps; ++i) edge_positions.push_back(start + (stop - start) * i / gaps);
  add_end_lights(a, edge_positions);

  if (runway.b != nullptr) {
    const EndContext b = make_end(*runway.b, runway.a, width);
    const EndMarkings mb = add_end_markings(b);
    const double thresholds_apart = stop - runway.b->displaced_threshold_m;  // in a's frame
    centreline_to = thresholds_apart - mb.designation_end_m - centreline_clearance_m();
    stripes_to = thresholds_apart;
    widest = std::max(widest, b.options.category);
    std::vector<double> edge_positions_b;
    for (auto it = edge_positions.rbegin(); it != edge_positions.rend(); ++it) {
      edge_positions_b.push_back(thresholds_apart - *it);
    }
    add_end_lights(b, edge_positions_b);
  }
  add_paint(a, centreline_stripes(ma.designation_end_m + centreline_clearance_m(), centreline_to,
                                  centreline_width_m(widest)));
  if (widest == ApproachCategory::kPrecisionCatI ||
      widest == ApproachCategory::kPrecisionCatIIorIII) {
    add_paint(a, side_stripes(0.0, stripes_to, width));
  }
}

GeodeticPosition reference_point(const std::vector<const RunwayEndRecord*>& ends) {
  double lat = 0.0, lon = 0.0;
  for (const auto* e : ends) {
    lat += e->threshold.lat_rad + e->end.lat_rad;
    lon += e->threshold.lon_rad + e->end.lon_rad;
  }
  const double n = 2.0 * static_cast<double>(ends.size());
  return {lat / n, lon / n, 0.0};
}

}  // namespace

void validate(const RunwayEndRecord& r) {
  const std::string where = where_of(r);
  check_point(r.threshold, where, "threshold");
  check_point(r.end, where, "end");
  util::require_in_range(r.heading_true_rad, -units::kTwoPi, units::kTwoPi, where, "heading_true_rad",
                   "rad");
  util::require_in_range(r.length_m, 100.0, 10000.0, where, "length_m", "m");
  util::require_in_range(r.width_m, 0.0, 200.0, where, "width_m", "m");
  util::require_in_range(r.displaced_threshold_m, 0.0, r.length_m - 100.0, where, "displaced_threshold_m",
                   "m");
  parse_designator(r.runway, where);
}

Scene build_airport_scene(const std::vector<RunwayEndRecord>& ends,
                          const AirportSceneOptions& options) {
  std::vector<const RunwayEndRecord*> open;
  std::vector<std::string> notes;
  for (const auto& e : ends) {
    validate(e);
    if (e.closed) {
      notes.push_back(where_of(e) + ": closed, left out");
    } else {
      open.push_back(&e);
    }
  }
  if (open.empty()) throw std::invalid_argument("build_airport_scene: no open runway ends given");
  util::require_in_range(options.unknown_width_m, 5.0, 200.0, "AirportSceneOptions", "unknown_width_m",
                   "m");
  for (const auto& [name, o] : options.ends) {
    util::require_in_range(o.glide_path_rad, 1.0 * units::kDegToRad, 8.0 * units::kDegToRad,
                     "AirportSceneOptions end " + name, "glide_path_rad", "rad");
  }
  util::require_in_range(options.default_end.glide_path_rad, 1.0 * units::kDegToRad,
                   8.0 * units::kDegToRad, "AirportSceneOptions default_end", "glide_path_rad",
                   "rad");

  double lowest = std::numeric_limits<double>::infinity();
  for (const auto* e : open)
    lowest = std::min({lowest, e->threshold.elevation_m, e->end.elevation_m});
  GeodeticPosition origin =
      options.reference_point ? *options.reference_point : reference_point(open);
  origin.alt_m = lowest - kGroundBelowM;

  Scene scene{SceneFrame(origin)};
  scene.ground_elevation_m = origin.alt_m;
  scene.notes = notes;
  SceneBuilder builder(scene, options);
  for (const Runway& r : pair_ends(open)) builder.add_runway(r);
  return scene;
}

}  // namespace fedsim::visual
