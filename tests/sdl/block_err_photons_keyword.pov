sphere { 0, 1 photons { target spacing 0.1 } }
