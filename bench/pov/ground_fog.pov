// ground_fog.pov (bench/pov_side.sh): POV-Ray's ground fog (fog_type 2): dense below fog_offset,
// thinning above it over fog_alt, among tall boxes.
global_settings { assumed_gamma 1 }
camera { location <0, 3, -8> look_at <0, 1.5, 4> angle 55 }
light_source { <-6, 12, -8> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
fog { fog_type 2 distance 3 color rgb <0.85, 0.85, 0.9> fog_offset 0.5 fog_alt 0.6 }
plane { y, 0 pigment { color rgb <0.4, 0.5, 0.3> } finish { ambient 0 } }
#declare I = 0;
#while (I < 5)
  box { <-4 + I * 2, 0, 2 + I * 2>, <-3 + I * 2, 4, 3 + I * 2> pigment { color rgb <0.8, 0.6, 0.4> } finish { ambient 0 } }
  #declare I = I + 1;
#end
