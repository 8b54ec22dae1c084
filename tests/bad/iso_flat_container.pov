isosurface {
  function { x }
  contained_by { box { <-1, 0, -1>, <1, 0, 1> } }
}
