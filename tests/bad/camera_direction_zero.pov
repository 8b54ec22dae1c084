// A camera direction of length zero has no view.
camera { location -z direction 0 }
