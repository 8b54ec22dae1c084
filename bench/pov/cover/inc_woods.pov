// inc_woods.pov (bench/pov_cover.sh): woods.inc's layered T_Wood1, T_Wood10 and T_Wood20
#version 3.7;
#include "woods.inc"
#declare TA = texture { T_Wood1 scale 0.5 }
#declare TB = texture { T_Wood10 scale 0.5 }
#declare TC = texture { T_Wood20 scale 0.5 }
#include "inc_stage.inc"
