// head.pov: the Lee Perry-Smith head scan (Infinite-Realities, CC BY 3.0; see
// scenes/assets/lee_perry_smith_head) in skin with its colour and normal maps, as scenes/default.pov,
// seen in profile with a light behind it so the ear glows and a weaker key from the front.
#version 3.7;
global_settings { mm_per_unit 22 max_trace_level 6 }
camera { location <15, 1.2, 6> look_at <0, 0.6, 0> angle 40 }
light_source { <-6, 10, -8> color rgb <1, 0.94, 0.86> intensity 500 }
light_source { <14, 6, 12> color rgb 1 intensity 120 }
background { color rgb 0 }
mesh {
  file "../../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj"
  material {
    skin {
      image "../../../scenes/assets/lee_perry_smith_head/Map-COL.jpg"
      normal_map "../../../scenes/assets/lee_perry_smith_head/Infinite-Level_02_Tangent_SmoothUV.jpg"
        strength 1
    }
  }
}
