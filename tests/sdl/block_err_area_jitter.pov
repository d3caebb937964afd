light_source { <0, 5, 0>, 1 jitter }
