// superellipsoid: rounded box (small e, n), pinched star (e, n > 1), a sphere (1, 1), a
// cylinder-like one (n small) in a difference, one with e = n = 0.05 seen edge-on (grazing
// rays along its faces), turned and scaled.
#include "algebraic_common.inc"
superellipsoid { <0.2, 0.2> pigment { rgb <1, 0.5, 0.3> } scale 0.8 translate <-2.4, 0, 0> }
superellipsoid { <2.5, 2> pigment { rgb <0.4, 0.8, 0.4> } rotate <20, 30, 0> translate <-0.8, 0.2, 0> }
superellipsoid { <1, 1> pigment { rgb <0.9, 0.9, 0.9> } scale 0.6 translate <0.8, 0.6, -1> }
difference {
  superellipsoid { <1, 0.1> rotate <90, 0, 0> }
  superellipsoid { <0.5, 0.5> scale 0.7 translate <0, 0.6, 0> }
  pigment { rgb <0.4, 0.6, 1> } scale 0.8 translate <2.3, 0, 0.3> }
superellipsoid { <0.05, 0.05> pigment { rgb <1, 0.9, 0.4> }
  scale <1.5, 0.2, 0.4> translate <0, -1.3, -2.2> }
