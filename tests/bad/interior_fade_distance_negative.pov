#declare I_Bad = interior {
  ior 1.5
  fade_distance -1
  fade_power 2
}
