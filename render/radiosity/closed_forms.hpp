// Closed-form view factors from the heat-transfer catalogues. They
// are the references the numerical form factors are tested against.
#pragma once

namespace lumen::render::radiosity::closed_form {

// (a) differential area to a parallel coaxial disc of radius r at height h.
double point_to_coaxial_disc(double h, double r);
// (b) disc r1 to a parallel coaxial disc r2 at distance h.
double coaxial_discs(double r1, double r2, double h);
// (c) directly opposed parallel a x b rectangles at distance c.
double parallel_rectangles(double a, double b, double c);
// (d) perpendicular rectangles with a common edge of length l: emitter width w, receiver
// height h (both measured perpendicular to the edge).
double perpendicular_rectangles(double l, double w, double h);
// (f) differential area below a corner of a parallel a x b rectangle at height c.
double point_below_rectangle_corner(double a, double b, double c);

}  // namespace lumen::render::radiosity::closed_form
