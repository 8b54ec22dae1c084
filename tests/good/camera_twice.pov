// POV-Ray uses the last camera of a scene (screen.inc's Set_Camera_* macros declare one at each
// call): circe too, with a warning at the second and a note at the first.
camera { location <0, 0, -5> look_at 0 }
camera { location <0, 3, -5> look_at 0 angle 40 }
sphere { 0, 1 }
