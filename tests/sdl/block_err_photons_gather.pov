global_settings { photons { spacing 0.1 gather 50, 20 } }
