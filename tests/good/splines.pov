// splines: every kind of POV-Ray 3.7 spline at keys inside, between and outside its entries, copies and
// kind changes, 2-, 3- and 5-component values; splines.stderr is what povray 3.7.0 printed for this file.
#declare S1 = spline { linear_spline 0, <0,1,2> 1, <1,3,-1>, 2.5, <2,2,2> 4, <-1,0,5> 3, <0.5,0.5,0.5> }
#declare S2 = spline { S1 quadratic_spline }
#declare S3 = spline { S1 cubic_spline }
#declare S4 = spline { S1 natural_spline }
#declare S5 = spline { cubic_spline 0, 1 1, 3 }
#declare S6 = spline { cubic_spline 0, 1 1, 3 2, -1 }
#declare S7 = spline { natural_spline 0, 1 1, 3 }
#declare S8 = spline { quadratic_spline 0, <1,1> 2, <3,5> }
#declare S9 = spline { 5, <1,2,3,4,5> }
#declare S10 = spline { S1 3, <9,9,9> 1.5, <7,7,7> }
#declare S11 = spline { natural_spline 0, 1 0.5, 3 1.5, -1 2, 4 3, 0 }
#declare S12 = spline { cubic_spline -1, <0,0> 0, <1,1> 0.5, <2,-1> 2, <3,3>, 2.5, <0,0> 4, <1,2> }
#declare I = -1;
#while (I <= 5)
#debug concat(str(I,0,2), "\n")
#debug concat(vstr(3, S1(I), ",", 0, 9), " ", vstr(3, S2(I), ",", 0, 9), "\n")
#debug concat(vstr(3, S3(I), ",", 0, 9), " ", vstr(3, S4(I), ",", 0, 9), "\n")
#debug concat(vstr(2, S5(I), ",", 0, 9), " ", vstr(2, S6(I), ",", 0, 9), " ", vstr(2, S7(I), ",", 0, 9), "\n")
#debug concat(vstr(2, S8(I), ",", 0, 9), "\n")
#debug concat(vstr(5, S9(I), ",", 0, 9), "\n")
#debug concat(vstr(3, S10(I), ",", 0, 9), " ", vstr(2, S11(I), ",", 0, 9), "\n")
#debug concat(vstr(3, S1(I, natural_spline), ",", 0, 9), " ", vstr(2, S12(I), ",", 0, 9), "\n")
#declare I = I + 0.125;
#end
