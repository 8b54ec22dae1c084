#declare A = 1;
object { A }
