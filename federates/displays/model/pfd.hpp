// The primary flight display (seed 5.8: the attitude indicator, altimeter, airspeed indicator
// and compass card of an EFIS), laid out as a Boeing 737-style PFD: the attitude sphere in the
// middle (sky and ground, a pitch ladder every 2.5/5/10 deg, the fixed bank scale with the
// moving bank pointer and the slip/skid trapezoid, the aircraft symbol, flight director bars,
// the localizer scale at its foot and the glide-slope scale at its right, marker beacon and
// radio altitude), the speed tape on the left and the altitude tape on the right (each with
// its readout box, trend vector, selected bug and readout), the vertical speed indicator at the
// far right, a heading arc at the bottom and the flight mode annunciator along the top.
//
// Design units: the PFD is drawn in a 1000 x 1000 square (y down) fitted to the picture's
// shorter side and centred; PfdLayout gives where its parts fall in pixels.
// Scales: pitch 10 units/deg; speed 4 units/kt; altitude 0.4 units/ft; localizer and glide
// slope 50 units/dot; vertical speed 100 units per 1000 ft/min to 1000, then 50 to 2000, then
// 10 per 1000 to 6000 (the 737's non-linear VSI).
#pragma once

#include "common/symbology/canvas.hpp"
#include "displays/model/display_inputs.hpp"

namespace fedsim::displays {

struct PfdLayout {
  double px_per_unit = 1.0;                 // [px per design unit]
  symbology::Vec2 origin_px = symbology::Vec2::Zero();            // where the design square's top-left corner falls
  symbology::Vec2 adi_centre_px = symbology::Vec2::Zero();        // the aircraft symbol's centre: pitch and roll zero
  double pixels_per_degree = 0.0;           // pitch scale [px/deg]
  symbology::Rect adi_px;                              // the attitude sphere's window
  symbology::Vec2 localizer_centre_px = symbology::Vec2::Zero();  // the localizer scale's centre (0 dots)
  double localizer_dot_px = 0.0;            // one dot [px]
  symbology::Rect localizer_scale_px;                  // where its pointer or flag is drawn
  symbology::Vec2 glideslope_centre_px = symbology::Vec2::Zero();
  double glideslope_dot_px = 0.0;
  symbology::Rect glideslope_scale_px;
  symbology::Rect speed_readout_px;     // the speed readout box
  symbology::Rect altitude_readout_px;  // the altitude readout box
  symbology::Rect flight_director_flag_px;

  symbology::Vec2 to_px(const symbology::Vec2& design) const { return origin_px + px_per_unit * design; }
  symbology::Rect to_px(const symbology::Rect& design) const;
};

PfdLayout pfd_layout(int width_px, int height_px);

/// Draws the PFD into `canvas` (reset to the picture's size first); inputs validated.
void draw_pfd(symbology::Canvas& canvas, const PfdInputs& in);

}  // namespace fedsim::displays
