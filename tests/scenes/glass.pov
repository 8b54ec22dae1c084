// glass.pov: transparency and interiors (doc/language.md "Transparency and interiors"): a clear
// glass ball (ior 1.5), a ruby ball with an exponential fade, a water ball with a filter tint, on a
// checker of boxes, behind them a thin filtering and transmitting plane before a lit wall, and a
// transmitting pane (no interior: straight through) in front. Shadows pass the glass tinted.
// render: -W 64 -H 48 --spp 16 --seed 3
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 2.2, -7> look_at <0, 0.9, 0> angle 45 }
light_source { <5, 9, -6> color rgb 3 }
light_source { <-6, 6, -3> color rgb 1.5 }
#declare I = -6;
#while (I < 6)
  #declare J = -4;
  #while (J < 6)
    box { <I, -0.1, J>, <I + 1, 0, J + 1> pigment { color rgb 0.15 + 0.7 * mod(I + J + 100, 2) } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
plane { z, 2.5 pigment { color rgbf <0.3, 0.5, 1, 0.5> transmit 0.3 } }
box { <-6, 0, 4>, <6, 5, 4.2> pigment { color rgb <0.8, 0.7, 0.5> } }
#declare I_Ruby = interior { ior 1.5 fade_distance 1 fade_power 1001 fade_color rgb <0.9, 0.1, 0.2> }
sphere { <-2.2, 1, 0>, 1 pigment { color rgbf <1, 1, 1, 1> } interior { ior 1.5 } }
sphere { <0, 1, 0>, 1 material { texture { pigment { color rgbt <1, 1, 1, 0.95> } finish { diffuse 0 } } interior { I_Ruby } } }
sphere { <2.2, 1, 0>, 1 pigment { color rgbf <0.6, 0.9, 1, 0.9> } interior { ior 1.33 } }
box { <-3.4, 0, -2.2>, <-1.6, 1.2, -2.19> pigment { color rgbt <1, 1, 0.6, 0.7> } }
