#declare C = rgb "red";
