// object { L } of a declared light in a clipped_by's union: POV-Ray refuses it too ("Illegal
// texture or patch in clip, bound or object pattern")
#declare L = light_source { <1, 0, 0> color 1 }
sphere { 0, 1 clipped_by { union { object { L } box { -1, 1 } } } }
