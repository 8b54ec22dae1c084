// vector_comma: a comma may stand before a vector's closing > (animations/float4 writes
// rgb<0.2,0.1,0.5,>). vector_comma.stderr is what povray 3.7.0 printed.
#declare C = rgb<0.2,0.1,0.5,>;
#declare V = <1, 2,>;
#declare W = <1, 2, 3 , >;
#debug concat(vstr(5, C, ",", 0, 2), " ", vstr(2, V, ",", 0, 0), " ", vstr(3, W, ",", 0, 0), "\n")
