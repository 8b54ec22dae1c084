// bench/cycles/textured.pov: issue 20's second comparison scene, scenes/default.pov's set-up for
// Blender's Cycles (bench/cycles/scene.py builds the same one, its SCENE "textured"): the Lee
// Perry-Smith head in skin with its colour and normal maps, default.pov's warm sphere light and
// studio environment. The skin is head.pov's (radius <1.35, 1.14, 0.99> mm, roughness 0.35,
// ior 1.4, profile burley: Cycles 3.4 has no sum of Gaussians), its colour the colour map's.
// Every number here has its twin in scene.py: change both.
#version 3.7;
global_settings { mm_per_unit 22 max_trace_level 6 }
camera { location <4.5, 1.5, 17> look_at <0, 0.6, 0> angle 34 }
light_source { <-10, 12, 16> color rgb <1, 0.94, 0.86> intensity 450 radius 1.5 }
sky_sphere { image "../../scenes/assets/studio/studio.exr" intensity 0.5 }
mesh {
  file "../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj"
  material {
    skin {
      image "../../scenes/assets/lee_perry_smith_head/Map-COL.jpg"
      normal_map "../../scenes/assets/lee_perry_smith_head/Infinite-Level_02_Tangent_SmoothUV.jpg" strength 1
      radius <1.35, 1.14, 0.99> roughness 0.35 ior 1.4 profile burley
    }
  }
}
