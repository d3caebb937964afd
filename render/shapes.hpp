// The primitive shapes prepared for intersection, in object space: one header and source file
// per shape of scene/shape_list.hpp in render/shapes/ (shape.hpp says what each provides).
#pragma once
#include "render/shapes/box.hpp"
#include "render/shapes/cone.hpp"
#include "render/shapes/disc.hpp"
#include "render/shapes/lathe.hpp"
#include "render/shapes/mesh.hpp"
#include "render/shapes/plane.hpp"
#include "render/shapes/poly.hpp"
#include "render/shapes/polygon.hpp"
#include "render/shapes/prism.hpp"
#include "render/shapes/sor.hpp"
#include "render/shapes/quadric.hpp"
#include "render/shapes/sphere.hpp"
#include "render/shapes/superellipsoid.hpp"
#include "render/shapes/text.hpp"
#include "render/shapes/torus.hpp"
#include "render/shapes/triangle.hpp"
