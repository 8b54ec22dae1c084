// A '#' that no directive name follows is dropped, as povray 3.7.0 does (its
// language/image_size.pov has `look_at <0,2,0>#` before the camera's '}'), with a warning.
camera { location <0, 2, -10> look_at <0, 2, 0>#
}
sphere { 0, 1 }
# 
