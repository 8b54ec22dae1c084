parametric {
  function { u } function { v } function { 0 }
  <0, 1>, <1, 1>
}
