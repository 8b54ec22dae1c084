difference {
  sphere { 0, 1 }
  box { -1, 1 }
}
