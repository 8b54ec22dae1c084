// A declared light_source is placed with light_source { Name }.
#declare L = light_source { <0, 9, 0>, 1 }
L
