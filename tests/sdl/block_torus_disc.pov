torus { 2, 0.5 }
torus { 1, 0.1 sturm rotate x*90 }
disc { <0, 1, 0>, <0, 0, 2>, 3 }
disc { 0, y, 2, 1 }
