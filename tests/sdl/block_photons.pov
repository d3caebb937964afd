// photons { } in global_settings, on objects (CSG children inherit a union's) and on lights.
global_settings {
  photons { spacing 0.02 gather 10, 50 jitter 0.2 autostop 0 expand_thresholds 0.1, 20
            radius 0.1, 2 max_trace_level 8 adc_bailout 0.01 }
}
light_source { <0, 5, 0> rgb 1 photons { refraction on reflection off area_light } }
sphere { 0, 1 photons { target 0.5 refraction on reflection on collect off } }
union { sphere { 0, 1 } box { -1, 1 } photons { pass_through } }
plane { y, 0 photons { collect off } }
