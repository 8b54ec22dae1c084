// glass_inc.pov: glass.inc's colours, finishes and interiors in a minimal scene, for
// bench/glass_inc.sh (circe beside POV-Ray 3.7).
#include "glass.inc"
camera { location <0, 2.2, -7> look_at <0, 0.9, 0> angle 45 }
light_source { <5, 9, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.5 }
#declare I = -6;
#while (I < 6)
  #declare J = -4;
  #while (J < 8)
    box { <I, -0.1, J>, <I + 1, 0, J + 1> pigment { color rgb 0.15 + 0.7 * mod(I + J + 100, 2) } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
box { <-6, 0, 4>, <6, 5, 4.2> pigment { color rgb <0.8, 0.7, 0.5> } }
sphere { <-2.2, 1, 0>, 1 texture { T_Glass1 } interior { I_Glass } }
sphere { <0, 1, 0>, 1 material { texture { pigment { Col_Glass_Ruby } finish { F_Glass5 } } interior { I_Glass1 } } }
sphere { <2.2, 1, 0>, 1 texture { pigment { Col_Glass_Winebottle } finish { F_Glass9 } } interior { I_Glass_Fade_Exp2 } }
