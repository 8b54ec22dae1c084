// crlf: a scene with CRLF line endings.
camera { location <0, 0, -5>
  look_at 0 }
sphere { 0, 1 }
#declare A = 2;
box { -A, A }
