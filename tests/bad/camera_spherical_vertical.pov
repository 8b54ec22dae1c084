camera { spherical angle 360, 200 }
