// pavement's triangular (number_of_sides 3, POV-Ray's default) and hexagonal (6) cells: the
// value at (x, z) of a layout's tiles, shaped by exterior, interior and form. How a layout's
// table covers the cells is told in scene/pavement_layouts_triangles.inc and
// scene/pavement_layouts_hexagons.inc; square cells are in render/patterns/pavement.cpp.
#pragma once

#include "scene/pattern.hpp"
#include "scene/pavement_layouts.hpp"

namespace lumen::render {

double triangle_cells(const scene::PavementLayout& l, const scene::pattern::Pavement& k, double x,
                      double z);
double hexagon_cells(const scene::PavementLayout& l, const scene::pattern::Pavement& k, double x,
                     double z);

}  // namespace lumen::render
