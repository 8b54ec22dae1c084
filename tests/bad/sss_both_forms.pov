sphere { 0, 1
  material { skin { sigma_s <1, 1, 1> radius <1, 1, 1> } }
}
