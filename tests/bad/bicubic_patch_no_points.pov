// a bicubic_patch needs its 16 control points
bicubic_patch { type 1 }
