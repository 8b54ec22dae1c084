// a camera normal on a fisheye camera: circe bends perspective and orthographic rays only
camera { fisheye location <0, 0, -5> look_at 0 normal { bumps 0.2 } }
