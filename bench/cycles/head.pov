// bench/cycles/head.pov: issue 20's comparison set-up, the scene Blender's Cycles renders beside
// circe (bench/cycles/scene.py builds the same one in Blender): the Lee Perry-Smith head in skin
// without textures (colour <0.8, 0.55, 0.45>, radius <1.35, 1.14, 0.99> mm, roughness 0.35), one
// sphere light of radius 1 above, in front and to the right, a dim constant background.
// Every number here has its twin in scene.py: change both.
#version 3.7;
global_settings { mm_per_unit 22 max_trace_level 6 }
camera { location <4.5, 1.5, 17> look_at <0, 0.6, 0> angle 34 }
light_source { <8, 8, 14> color rgb 1 intensity 300 radius 1 }
background { color rgb 0.05 }
mesh {
  file "../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj"
  material { skin { color rgb <0.8, 0.55, 0.45> radius <1.35, 1.14, 0.99> roughness 0.35 ior 1.4
                    profile burley } }
}
