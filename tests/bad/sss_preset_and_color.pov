sphere { 0, 1
  material { marble { color rgb 0.5 preset "marble" } }
}
