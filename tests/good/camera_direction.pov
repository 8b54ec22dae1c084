// camera_direction: POV-Ray's camera direction: without look_at it is where the camera looks;
// without angle its length sets the field of view against right's, 2 atan(|right| / (2 |direction|)),
// here 2 atan(1.5 / 4) = 41.1 degrees (as POV-Ray's samples landscape.pov and camera2.pov use it).
#declare Cam = camera { location <3, 2.3, 0.3> direction 2 * y sky z up z right x * 1.5 }
camera { Cam }
sphere { 0, 1 }
