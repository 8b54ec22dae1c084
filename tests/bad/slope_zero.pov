// A slope pattern needs a direction or an altitude of some length
sphere { 0, 1 pigment { slope { <0, 0, 0> altitude 0 } } }
