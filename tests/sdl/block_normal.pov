// Normal perturbation is recorded but not rendered yet: listed as unsupported.
sphere { 0, 1 normal { bumps 0.4 scale 0.2 } }
sphere { 0, 1 normal { gradient x bump_size 2 } }
