// bunny.pov: the Stanford bunny (see scenes/assets/bunny) in wax, about 3 cm tall, lit from behind
// and above so the ears glow; a weak light from the camera fills the rest.
#version 3.7;
global_settings { mm_per_unit 3 }
camera { location <0, 5, -22> look_at <0, 4.6, 0> angle 32 }
light_source { <-16, 12, 10> color rgb 1 intensity 1500 }
light_source { <4, 8, -20> color rgb 1 intensity 80 }
background { color rgb 0 }
mesh { file "../../../scenes/assets/bunny/bunny_npm.obj" material { wax {} } }
