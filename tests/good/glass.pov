// Transparency and interiors (doc/language.md): filter and transmit of a pigment, interiors
// given on the object, inside a material, declared, and POV-Ray's words circe accepts and ignores.
#declare I_Fade = interior { ior 1.5 fade_distance 2 fade_power 1001 fade_color rgb <0.2, 0.4, 1> }
#declare I_Copy = interior { I_Fade fade_power 2 }
#declare M_Glass = material { texture { pigment { rgbf <0.9, 1, 0.9, 0.8> } finish { diffuse 0.1 } } interior { I_Copy } }
#declare T_Clear = texture { pigment { color rgbt <1, 1, 1, 0.7> } }
camera { location <0, 1, -5> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
sphere { <-1.5, 0, 0>, 1 pigment { rgbf <1, 0.5, 0.5, 0.9> } interior { ior 1.33 } }
sphere { <0, 0, 0>, 1 material { M_Glass } }
sphere { <1.5, 0, 0>, 1 texture { T_Clear } interior { I_Fade dispersion 1.02 caustics 0.5 } }
box { <-3, -1.2, 1>, <3, 1.5, 1.1> pigment { color rgb <0.2, 0.3, 0.9> filter 0.5 transmit 0.2 } }
plane { y, -1 material { interior { ior 1.2 } texture { pigment { rgbt <1, 1, 1, 0.3> } } } }
