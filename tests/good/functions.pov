// functions: POV-Ray 3.7's float, vector and string functions that need no geometry, printed with
// #debug (good_scenes.sh compares functions.stderr). Checked against povray 3.7.0: the same file
// printed the same lines (but the last: rand's numbers are PCG32's, not POV-Ray's, so only their
// properties are printed, which povray gives alike).
#declare Q = 1;
#debug concat(str(sin(pi/6), 0, 6), " ", str(cos(0), 0, 6), " ", str(tan(pi/4), 0, 6), "\n")
#debug concat(str(asin(1), 0, 6), " ", str(acos(0), 0, 6), " ", str(atan(1), 0, 6), " ", str(atan2(1, -1), 0, 6), "\n")
#debug concat(str(sinh(1), 0, 6), " ", str(cosh(1), 0, 6), " ", str(tanh(1), 0, 6), "\n")
#debug concat(str(asinh(1), 0, 6), " ", str(acosh(2), 0, 6), " ", str(atanh(0.5), 0, 6), "\n")
#debug concat(str(sqrt(2), 0, 6), " ", str(exp(1), 0, 6), " ", str(log(1000), 0, 6), " ", str(ln(10), 0, 6), " ", str(pow(2, 10), 0, 6), "\n")
#debug concat(str(abs(-3.5), 0, 1), " ", str(floor(-2.5), 0, 1), " ", str(ceil(-2.5), 0, 1), " ", str(int(-2.5), 0, 1), " ", str(int(2.7), 0, 1), "\n")
#debug concat(str(div(7, 2), 0, 1), " ", str(div(-7, 2), 0, 1), " ", str(mod(7, 3), 0, 1), " ", str(mod(-7, 3), 0, 1), " ", str(mod(7.5, 2), 0, 1), "\n")
#debug concat(str(min(3, 1, 2), 0, 1), " ", str(max(3, 1, 2), 0, 1), " ", str(min(5, 4), 0, 1), "\n")
#debug concat(str(select(-1, 10, 20), 0, 0), " ", str(select(0, 10, 20), 0, 0), " ", str(select(-1, 10, 20, 30), 0, 0), " ", str(select(0, 10, 20, 30), 0, 0), " ", str(select(2, 10, 20, 30), 0, 0), "\n")
#debug concat(str(radians(180), 0, 6), " ", str(degrees(pi/2), 0, 6), "\n")
#debug concat(str(bitwise_and(12, 10), 0, 0), " ", str(bitwise_or(12, 10), 0, 0), " ", str(bitwise_xor(12, 10), 0, 0), " ", str(bitwise_and(7, 6, 3), 0, 0), "\n")
#debug concat(vstr(3, vaxis_rotate(<1, 0, 0>, <0, 0, 1>, 90), ", ", 0, 6), " / ", vstr(3, vrotate(<1, 0, 0>, <0, 0, 90>), ", ", 0, 6), "\n")
#debug concat(vstr(3, vaxis_rotate(<0, 1, 0>, <1, 0, 0>, 90), ", ", 0, 6), " / ", vstr(3, vrotate(<0, 1, 0>, <90, 0, 0>), ", ", 0, 6), "\n")
#debug concat(vstr(3, vnormalize(<3, 0, 4>), ", ", 0, 3), " ", str(vlength(<3, 4, 12>), 0, 1), " ", str(vdot(<1, 2, 3>, <4, 5, 6>), 0, 1), " ", vstr(3, vcross(x, y), ", ", 0, 1), "\n")
#debug concat(vstr(3, vnormalize(<1, 1>), ", ", 0, 3), "\n")
#debug concat("[", str(3.14159, 8, 2), "] [", str(3.14159, -8, 2), "] [", str(2.5, 0, -1), "] [", str(-2, 0, 0), "]\n")
#debug concat("[", vstr(2, <1, 2>, ",", 0, 1), "] [", vstr(5, <1, 2, 3>, ",", 0, 0), "] [", vstr(4, 7, " ", 3, 0), "]\n")
#debug concat(chr(65), chr(98), " ", str(asc("A"), 0, 0), " ", str(strlen("hello"), 0, 0), " ", substr("abcdef", 2, 3), " ", strupr("MiXed"), " ", strlwr("MiXed"), "\n")
#debug concat(str(strcmp("abc", "abd"), 0, 0), " ", str(strcmp("b", "a"), 0, 0), " ", str(strcmp("x", "x"), 0, 0), " ", str(val("2.5e1"), 0, 1), " ", str(val(" -3"), 0, 1), "\n")
#debug concat(datetime(0), " | ", datetime(366.5, "%Y-%m-%d %H:%M"), "\n")
#debug concat(str(file_exists("functions.pov"), 0, 0), str(file_exists("no such file"), 0, 0), " ", substr("abc", 4, 0), "|", substr("abc", 1, 3), "\n")
#declare S1 = seed(7); #declare S2 = seed(7);
#declare R1 = rand(S1); #declare R2 = rand(S2);
#debug concat(str((R1 = R2), 0, 0), " ", str((R1 >= 0 & R1 < 1), 0, 0), " ", str((rand(S1) != R1), 0, 0), " ", str(strcmp("a", "c"), 0, 0), "\n")
sphere { 0, 1 }
