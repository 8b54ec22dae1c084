// sky_image_map.pov (bench/pov_cover.sh): a sky_sphere of an image_map (map_type 1, povray-includes'
// povmap.png), the camera looking up over a plane
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -6> look_at <0, 3, 0> angle 90 }
sky_sphere { pigment { image_map { png "povmap.png" map_type 1 interpolate 2 } } }
plane { y, 0 pigment { rgb 0.5 } }
light_source { <-5, 8, -7> color rgb 1 }
