#declare C = rgb 1;
box { C, 1 }
