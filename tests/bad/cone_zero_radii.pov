union {
  sphere { 0, 1 }
  cone { 0, 0, y, 0 }
}
