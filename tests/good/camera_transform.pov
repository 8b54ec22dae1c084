// camera_transform: a camera's transforms move what was set before them, as POV-Ray's do: the
// location and look_at as points, sky, right and up as directions (a roll of 90 degrees about z
// turns sky and up to -x, then the turn about y takes them to +z); a look_at after them is in
// world space.
camera { location <0, 0, -5> look_at 0 rotate z * 90 rotate y * 90 translate y look_at <0, 1, 0> }
sphere { 0, 1 }
