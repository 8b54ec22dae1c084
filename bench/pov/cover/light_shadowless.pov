// light_shadowless.pov (bench/pov_cover.sh): a shadowless light beside a point light: it lights, casts no shadow
#include "light_stage.inc"
light_source { <-6, 9, -6> color rgb 0.6 }
light_source { <6, 3, -6> color rgb 0.6 shadowless }
