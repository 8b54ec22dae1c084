// inc_finish.pov (bench/pov_cover.sh): finish.inc's Dull, Phong_Shiny and Glossy
#version 3.7;
#include "finish.inc"
#declare TA = texture { pigment { rgb <0.8, 0.2, 0.15> } finish { Dull } }
#declare TB = texture { pigment { rgb <0.2, 0.7, 0.25> } finish { Phong_Shiny } }
#declare TC = texture { pigment { rgb <0.2, 0.3, 0.9> } finish { Glossy } }
#include "inc_stage.inc"
