// sphere.pov: a wax sphere of radius 10 mm lit from the side and slightly behind, so light bleeds
// past the terminator; a weak light from the camera fills the rest.
#version 3.7;
global_settings { mm_per_unit 10 }
camera { location <0, 0.6, -4> look_at <0, 0, 0> angle 36 }
light_source { <5, 1.5, 1.5> color rgb 1 intensity 40 }
light_source { <-3, 1, -6> color rgb 1 intensity 4 }
background { color rgb 0 }
sphere { <0, 0, 0>, 1 material { wax {} } }
