// #version sets the language version of the scene; `version` reads it back.
#version 3.7;
sphere { <version, 0, 0>, 0.5 }
