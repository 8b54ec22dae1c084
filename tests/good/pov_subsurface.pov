// POV-Ray's subsurface syntax (doc/language.md "POV-Ray's subsurface"): global_settings switches it
// on (samples recorded and warned about, radiosity recorded), a finish's translucency (a colour or
// a float) on a texture whose object's interior gives the ior; one without an interior takes ior 1
// (warned about once); a finish without subsurface stays a plain texture.
#version 3.7;
global_settings { mm_per_unit 40 subsurface { samples 400, 40 radiosity on } }
#declare Wax = texture {
  pigment { rgb <0.8, 0.5, 0.01> }
  finish { diffuse 0.6 specular 0.6 roughness 0.1 subsurface { translucency <5, 3, 1> * 0.5 anisotropy 0.3 } }
}
sphere { 0, 1 texture { Wax } interior { ior 1.45 } }
sphere { x * 3, 1 texture { pigment { rgb 0.9 } finish { subsurface { translucency 0.4562 } } } }
sphere { -x * 3, 1 texture { pigment { rgb 0.9 } finish { diffuse 0.7 } } }
