sphere { 0, 1
  material { diffuse { rgb 1 } }
  material { diffuse { rgb 0.5 } }
}
