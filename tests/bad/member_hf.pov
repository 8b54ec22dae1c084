#declare C = rgb 1;
#declare H = C.hf;
