#declare S = spline {
  cubic_spline
}
