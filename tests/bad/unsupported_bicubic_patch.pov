bicubic_patch { type 1 }
