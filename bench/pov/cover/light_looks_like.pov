// light_looks_like.pov (bench/pov_cover.sh): a point light with looks_like (a glowing sphere seen by the camera, no shadow from it)
#include "light_stage.inc"
light_source { <0, 3.2, -1.5> color rgb 0.9 looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.9, 0.5> } finish { ambient 1 diffuse 0 } } } }
light_source { <-6, 9, -6> color rgb 0.4 }
