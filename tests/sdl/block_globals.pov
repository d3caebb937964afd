#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 12
  adc_bailout 0.01
  ambient_light rgb <0.5, 0.5, 1>
  irid_wavelength rgb <0.25, 0.18, 0.14>
  noise_generator 1
  number_of_waves 5
  charset utf8
}
