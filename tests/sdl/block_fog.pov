fog { distance 50 color rgbf <0.5, 0.6, 0.7, 0.2> }
fog { fog_type 2 distance 10 color rgb 1 fog_offset 0.5 fog_alt 1.5 up z rotate x*10 }
fog { distance 5 color rgb 0.5 turbulence 0.3 turb_depth 0.2 }
