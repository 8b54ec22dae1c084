#declare F = 1;
#declare G = F[0];
