// a bicubic_patch type must be 0 or more ("Undefined bicubic patch type" in POV-Ray)
bicubic_patch { type -1 <0,0,0> }
