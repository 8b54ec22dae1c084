union {
  sphere { 0, 1 }
  cone { 0, 1, y, 0 }
}
