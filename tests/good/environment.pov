// environment: a lat-long sky sphere; escapes in strings.
sky_sphere { image "studio \"small\".exr" intensity 2 rotate <0, 45, 0> }
sphere { 0, 1 }
