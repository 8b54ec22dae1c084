// a light in a union written in a bounded_by: POV-Ray refuses it ("Illegal texture or patch in
// clip, bound or object pattern": a light_source is a patch object there)
sphere { 0, 2 bounded_by { union { box { -3, 3 } light_source { <0, 5, 0> color 1 } } } }
