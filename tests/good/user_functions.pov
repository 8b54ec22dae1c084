// user_functions: user-defined functions as POV-Ray 3.7 reads them: parameters named or x, y, z by default,
// declared floats captured when the function is defined, functions calling functions, the float
// built-ins, comparisons and logic, vector-valued functions (transform, spline) and their members,
// #local functions in a macro. user_functions.stderr is what povray 3.7.0 printed for this file.
#declare K = 3;
#declare F = function(a, b) { a*b + sin(a) + K }
#declare K = 100; // F keeps the 3 it saw
#debug concat(str(F(1, 2), 0, 9), "\n")
#declare G = function { x*x + y - z + F(x, 1) }
#debug concat(str(G(2, 3, 4), 0, 9), "\n")
#declare M = function { min(x, y, z, 7) + max(x, y) + select(x, 1, 2) + select(y - 3, 10, 20, 30) + mod(7, 3) + pow(2, 3) + abs(-1) + int(-2.5) + floor(-2.5) + ceil(2.1) }
#debug concat(str(M(1, 3, 2), 0, 9), "\n")
#declare L = function(p, q) { (p < q) + 2*(p <= q) + 4*(p = q) + 8*(p != q) + 16*(p >= q) + 32*(p > q) + 64*(p & q) + 128*(p | q) }
#debug concat(str(L(1, 2), 0, 0), " ", str(L(2, 2), 0, 0), " ", str(L(0, 3), 0, 0), " ", str(L(0, 0), 0, 0), "\n")
#declare T1 = function { sqrt(x) + exp(y) + ln(z) + log(x) + atan2(x, y) + sinh(y) + cosh(z) + tanh(x) + asin(y) + acos(y) + atan(z) + tan(x) + degrees(y) + radians(z) }
#debug concat(str(T1(2, 0.5, 3), 0, 9), "\n")
#declare Vf = function { 2*x - pi + clock }
#debug concat(str(Vf(3, 0, 0), 0, 9), "\n")
#declare S = spline { linear_spline 0, <0,0,0> 1, <1,2,3>, 2, <2,2,2> }
#declare Tr = function { transform { translate <1,2,3> scale 2 } }
#declare W = Tr(1, 1, 1);
#debug concat(vstr(3, W, ",", 0, 4), "\n")
#declare SF = function { spline { S } }
#debug concat(str(SF(1.5).y, 0, 4), " ", vstr(3, SF(0.25), ",", 0, 4), "\n")
#declare Q = function { SF(x).z + Tr(x, y, z).x }
#debug concat(str(Q(1.5, 0, 0), 0, 4), "\n")
#macro Twice(A)
  #local H = function(s) { 2*s }
  H(A)
#end
#debug concat(str(Twice(21), 0, 0), "\n")
#declare U = function(u, v) { u - v }
#debug concat(str(U(5, 3), 0, 0), "\n")
