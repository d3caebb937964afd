// Jitter probe (tools/jitter/measure_jitter.cpp): the colour of a sample tells where it was
// taken. An orthographic camera maps one pixel to one world unit, pixel centres on
// half-integers; red and green are saw-tooth ramps in x and y with a period of P = 2^-E pixel,
// phased so that a pixel centre reads 0.5. A sample d pixels from its pixel centre reads
// frac(0.5 + d/P). Rendered 256x256 with +A0.0 +AM1 +R1, every pixel is
// (centre + one jittered sample)/2. E is a power of two's exponent because a Declare= value
// on POV's command line loses digits (P = 2^-12 given as a decimal came out 1.5e-6 off).
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (E) #declare E = 0; #end
#declare P = pow(2, -E);
#declare Shift = (E = 0 ? 0 : P / 2);  // centres at half-integers: for P < 1 shift by P/2
#declare W = 256;
#declare H = 256;
camera { orthographic location <W / 2, H / 2, -10> look_at <W / 2, H / 2, 0> right x * W up y * H }
plane { -z, 0
  pigment { average pigment_map {
    [1 gradient x colour_map { [0 rgb <0, 0, 0>] [1 rgb <2, 0, 0>] } scale P translate x * Shift]
    [1 gradient y colour_map { [0 rgb <0, 0, 0>] [1 rgb <0, 2, 0>] } scale P translate y * Shift] } }
  finish { ambient 1 diffuse 0 specular 0 phong 0 }
}
