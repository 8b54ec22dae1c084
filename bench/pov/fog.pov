// fog.pov (bench/pov_side.sh): POV-Ray's constant fog over a row of spheres going into the distance.
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 4> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
fog { distance 12 color rgb <0.7, 0.75, 0.8> }
plane { y, 0 pigment { color rgb <0.5, 0.45, 0.4> } finish { ambient 0 } }
#declare I = 0;
#while (I < 6)
  sphere { <-1.5 + mod(I, 2) * 3, 1, I * 4>, 1 pigment { color rgb <0.9, 0.2, 0.2> } finish { ambient 0 phong 0.5 } }
  #declare I = I + 1;
#end
