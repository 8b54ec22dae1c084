// vectors: 2 to 5 components, POV-Ray 3.7's promotion (a float copied into every component, a
// shorter vector padded with zeros) and members; printed with #debug (vectors.stderr). Checked
// against povray 3.7.0: the same lines.
#declare V2 = <1, 2>;
#declare V3 = <1, 2, 3>;
#declare V4 = <1, 2, 3, 4>;
#declare V5 = <1, 2, 3, 4, 5>;
#debug concat(vstr(3, V2 + V3, ", ", 0, 1), " | ", vstr(4, V4 * 2, ", ", 0, 1), " | ", vstr(5, V5 - V2, ", ", 0, 1), "\n")
#debug concat(vstr(3, V3 + 1, ", ", 0, 1), " | ", vstr(2, 3 * V2, ", ", 0, 1), " | ", vstr(4, V4 / 2, ", ", 0, 1), "\n")
#debug concat(vstr(2, u, ", ", 0, 0), " ", vstr(2, v, ", ", 0, 0), " ", vstr(4, t, ", ", 0, 0), " ", vstr(3, x + y * 2 + z * 3, ", ", 0, 0), "\n")
#debug concat(str(V2.x, 0, 0), str(V2.y, 0, 0), str(V2.u, 0, 0), str(V2.v, 0, 0), " ", str(V3.z, 0, 0), " ", str(V4.t, 0, 0), " ", str(V5.transmit, 0, 0), str(V5.filter, 0, 0), " ", str(V3.gray, 0, 3), "\n")
#declare F = 7;
#debug concat(str(F.x, 0, 0), " ", str(<1, 2, 3>.y, 0, 0), " ", str((V3 * 2).z, 0, 0), "\n")
// a 2-vector where a 3-vector is expected: padded with z = 0
sphere { <1, 2>, 0.5 }
sphere { V3 * 2, 1 }
// box corners without a comma (POV-Ray's comma is optional): two vectors, not a comparison
box { <0, 0, 0><1, 1, 1> }
box { V3 <4, 4, 4> }
