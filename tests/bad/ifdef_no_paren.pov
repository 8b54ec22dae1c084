// #ifdef needs its parentheses, as in POV-Ray.
#declare A = 1;
#ifdef A #end
