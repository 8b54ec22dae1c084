parametric {
  function { u }
  function { v }
  <0, 0>, <1, 1>
}
