sphere { 0, 1
  clipped_by { bounded_by }
}
