light_group {
  light_source { <0, 5, 0> color 1 }
  sphere { 0, 1 }
  pigment { rgb 1 }
}
