// POV-Ray's atmospheric media: a media statement outside an interior fills the space around the
// objects; a second adds its own (as an interior's several media), a declared one copies.
#declare Haze = media { scattering { 1, rgb 0.02 } }
media { absorption 0.01 emission <0, 0, 0.01> }
media { Haze density { spherical scale 5 } }
box { -1, 1 pigment { rgb 1 } }
