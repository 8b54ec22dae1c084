// glass_inc.pov (bench/pov_cover.sh): glass.inc's glasses: T_Glass1 with I_Glass, Col_Glass_Ruby
// with F_Glass5 and I_Glass1, Col_Glass_Winebottle with F_Glass9 and I_Glass_Fade_Exp2.
#include "glass_stage.inc"
#include "colors.inc"
#include "glass.inc"
sphere { <-2.2, 1, 0>, 1 texture { T_Glass1 } interior { I_Glass } }
sphere { <0, 1, 0>, 1 material { texture { pigment { Col_Glass_Ruby } finish { F_Glass5 } } interior { I_Glass1 } } }
sphere { <2.2, 1, 0>, 1 texture { pigment { Col_Glass_Winebottle } finish { F_Glass9 } } interior { I_Glass_Fade_Exp2 } }
