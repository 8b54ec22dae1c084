// bench/cycles/lights.pov: issue 20's third comparison scene, several lights (bench/cycles/scene.py
// builds the same one, its SCENE "lights"): head.pov's head and skin and background, lit by three
// sphere lights of different sizes and colours: a warm key above-front-right (radius 1), a large
// cool fill to the left (radius 3), a small orange rim light behind and above (radius 0.3).
// Every number here has its twin in scene.py: change both.
#version 3.7;
global_settings { mm_per_unit 22 max_trace_level 6 }
camera { location <4.5, 1.5, 17> look_at <0, 0.6, 0> angle 34 }
light_source { <8, 8, 14> color rgb <1, 0.9, 0.8> intensity 200 radius 1 }
light_source { <-14, 2, 8> color rgb <0.6, 0.75, 1> intensity 150 radius 3 }
light_source { <-4, 10, -12> color rgb <1, 0.6, 0.3> intensity 300 radius 0.3 }
background { color rgb 0.05 }
mesh {
  file "../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj"
  material { skin { color rgb <0.8, 0.55, 0.45> radius <1.35, 1.14, 0.99> roughness 0.35 ior 1.4
                    profile burley } }
}
