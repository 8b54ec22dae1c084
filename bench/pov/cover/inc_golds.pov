// inc_golds.pov (bench/pov_cover.sh): golds.inc's T_Gold_1A, T_Gold_3C and T_Gold_5E
#version 3.7;
#include "golds.inc"
#declare TA = texture { T_Gold_1A }
#declare TB = texture { T_Gold_3C }
#declare TC = texture { T_Gold_5E }
#include "inc_stage.inc"
