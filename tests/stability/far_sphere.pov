// Stability: a radius-1 sphere 1e6 units from the camera, made large in view by a tiny
// camera angle (the image is 3.1 units wide at the sphere). Expected: a round flat-coloured disc
// (ambient only) centred in the image, identical when mirrored left-right and top-bottom,
// background in the corners, and the same image as POV-Ray. The width is not 3 units so that
// no pixel centre lies exactly on the rim: at 1e6 units whether an exactly tangent ray hits is
// decided by rounding in POV-Ray (its half chord subtracts two numbers near 1e12); exact
// tangents are tested near the origin in grazing.pov.
// expect: size 45x45
// expect: uniform 21 21 23 23 1 0.5 0.25 0
// expect: uniform 0 0 3 3 0 0 0.1 0
// expect: uniform 41 41 44 44 0 0 0.1 0
// expect: mirror-x 0
// expect: mirror-y 0
// expect: povray 45
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare D = 1e6;
camera { location <0, 0, -D> look_at <0, 0, 0> right x up y angle degrees(2 * atan2(1.55, D)) }
background { rgb <0, 0, 0.1> }
light_source { <0, 0, -2 * D> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> } finish { ambient 1 diffuse 0 } }
