// inc_stones.pov (bench/pov_cover.sh): stones.inc: stones1.inc's T_Stone8 and T_Grnt15, stones2.inc's
// layered T_Stone35
#version 3.7;
#include "colors.inc"
#include "stones.inc"
#declare TA = texture { T_Stone8 }
#declare TB = texture { T_Grnt15 }
#declare TC = texture { T_Stone35 }
#include "inc_stage.inc"
