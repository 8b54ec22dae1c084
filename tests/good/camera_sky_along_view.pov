// POV-Ray accepts a sky along the view (slopemt_dat_36.pov: location 22*y look_at 0): it warns and
// takes the right vector instead of sky x direction; and up parallel to direction under look_at
// (diffract.pov): a handedness of 0, a mirrored camera
camera { location 22 * y up z direction z right x look_at 0 }
sphere { 0, 1 }
