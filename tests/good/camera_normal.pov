// POV-Ray's camera normal { }: a normal pattern bending every camera ray (its render beside
// POV-Ray: bench/pov/camera_normal.pov).
camera { location <0, 2, -6> look_at <0, 1, 0> normal { leopard 0.6 scale 0.08 } angle 50 }
sphere { <0, 1, 0>, 1 }
