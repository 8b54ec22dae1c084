camera { location <0, 0, -5> look_at 0 }
light_source { <0, 5, 0> color rgb 1
	looks_like { sphere { 0, 1 } }
	looks_like { sphere { 0, 2 } }
}
