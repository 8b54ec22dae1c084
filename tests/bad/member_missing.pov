// A 2-vector has no .z (POV-Ray: "Bad operands for period operator").
#declare V = <1, 2>;
#declare Z = V.z;
