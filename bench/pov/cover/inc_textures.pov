// inc_textures.pov (bench/pov_cover.sh): textures.inc: Jade and Cherry_Wood pigments, Brushed_Aluminum
#version 3.7;
#include "textures.inc"
#declare TA = texture { pigment { Jade } }
#declare TB = texture { pigment { Cherry_Wood scale 0.3 } finish { phong 0.5 } }
#declare TC = texture { Brushed_Aluminum }
#include "inc_stage.inc"
