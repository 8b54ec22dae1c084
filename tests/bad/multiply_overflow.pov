#declare A = 1e200 * 1e200;
