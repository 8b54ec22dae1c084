// light_shadowless_phong.pov (bench/pov_cover.sh): light_shadowless.pov with highlights: the point
// light makes phong and specular highlights, the shadowless one (POV-Ray's fill light) none
#include "light_stage.inc"
#default { finish { phong 0.9 phong_size 30 specular 0.6 roughness 0.02 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb <0.85, 0.2, 0.15> } }
sphere { <0, 1, 0.5>, 1 pigment { rgb <0.2, 0.75, 0.25> } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <0.2, 0.3, 0.9> } }
light_source { <-6, 9, -6> color rgb 0.6 }
light_source { <6, 3, -6> color rgb 0.6 shadowless }
