global_settings {
  radiosity { count 100, 2000 error_bound 0.5 recursion_limit 3 nearest_count 8
              pretrace_start 0.04 pretrace_end 0.01 brightness 1.5 always_sample off
              normal on gray_threshold 0.2 }
  photons { count 20000 }
}
