// vrotate turns by x, then y, then z degrees (+y goes to +z about x); vaxis_rotate turns
// about an axis. Round() hides the 1e-17 leftovers of cos(90 degrees).
#macro Round(V) <floor(V.x * 1e6 + 0.5), floor(V.y * 1e6 + 0.5), floor(V.z * 1e6 + 0.5)> / 1e6 #end
sphere { Round(vrotate(<0, 1, 0>, <90, 0, 0>)), 0.5 }
sphere { Round(vrotate(<1, 0, 0>, <0, 90, 0>)), 0.5 }
sphere { Round(vrotate(<1, 0, 0>, <0, 0, 90>)), 0.5 }
sphere { Round(vaxis_rotate(<1, 0, 0>, <0, 1, 0>, 90)), 0.5 }
sphere { Round(vrotate(<1, 2, 3>, <10, 20, 30>)), 0.5 }
