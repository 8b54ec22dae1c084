// head_front.pov: the head of head.pov (the Lee Perry-Smith scan, CC BY 3.0) seen from the front,
// lit from the front only: a key above and beside the camera and a weak fill from the camera
// (issue 21's "head front-lit": thick by the light, though nose and ears are thin by the geometry).
#version 3.7;
global_settings { mm_per_unit 22 max_trace_level 6 }
camera { location <4.5, 1.5, 17> look_at <0, 0.6, 0> angle 34 }
light_source { <-10, 12, 16> color rgb <1, 0.94, 0.86> intensity 450 }
light_source { <4, 2, 18> color rgb 1 intensity 60 }
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
