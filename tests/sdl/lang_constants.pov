// Built-in constants: axis vectors, booleans, pi, image size (default 320x240).
sphere { x + 2 * y - z, pi / 4 }
sphere { <true + yes + on, false + no + off, image_width / image_height>, 0.5 }
